MODULE recur_binary
    ! Recursive string building: binary representation.
    FUNC string toBin(num n)
        IF n < 2 RETURN ValToStr(n);
        RETURN toBin(n DIV 2) + ValToStr(n MOD 2);
    ENDFUNC

    PROC main()
        TPWrite "0=" + toBin(0);
        TPWrite "10=" + toBin(10);
        TPWrite "255=" + toBin(255);
        TPWrite "256=" + toBin(256);
    ENDPROC
ENDMODULE
