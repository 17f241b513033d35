MODULE recur_factorial
    ! A recursive FUNC (manual 1.2.2: each call has its own routine data).
    FUNC num fact(num n)
        IF n <= 1 RETURN 1;
        RETURN n * fact(n - 1);
    ENDFUNC

    PROC main()
        TPWrite "0!=" \Num:=fact(0);
        TPWrite "1!=" \Num:=fact(1);
        TPWrite "5!=" \Num:=fact(5);
        TPWrite "8!=" \Num:=fact(8);
    ENDPROC
ENDMODULE
