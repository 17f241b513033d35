MODULE divmod_digits
    ! Split a number into decimal digits with MOD 10 and DIV 10.
    PROC main()
        VAR num n := 1234;
        VAR num sum := 0;
        VAR num digit;
        WHILE n > 0 DO
            digit := n MOD 10;
            TPWrite "digit=" \Num:=digit;
            sum := sum + digit;
            n := n DIV 10;
        ENDWHILE
        TPWrite "sum=" \Num:=sum;
    ENDPROC
ENDMODULE
