MODULE fmt_large_integers
    ! FORMAT-DEPENDENT. Integers with more than 6 digits print in exponent
    ! form under the 6-significant-digit rule (semantics 2.2, "(?)" on where
    ! exponent form starts; %G rules assumed).
    FUNC num fact(num n)
        IF n <= 1 RETURN 1;
        RETURN n * fact(n - 1);
    ENDFUNC

    PROC main()
        VAR num n := 999999;
        TPWrite "a=" \Num:=8388608;
        TPWrite "b=" \Num:=fact(10);
        TPWrite "c=" \Num:=500500;
        TPWrite "d=" \Num:=n + 1;
        TPWrite "e=" \Num:=16777216;
        TPWrite "f=" \Num:=-1234567;
        TPWrite "g=" + ValToStr(fact(9));
    ENDPROC
ENDMODULE
