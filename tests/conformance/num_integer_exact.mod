MODULE num_integer_exact
    ! Integers up to 8388608 are exact in num (semantics 2.1; manual 1.3.1
    ! note i: integer representation kept while inside the integer subdomain).
    ! Large values are compared, not printed, to stay clear of number formatting.
    PROC main()
        VAR num big := 8388608;
        VAR num n;
        VAR num sum := 0;
        n := big - 1;
        TPWrite "diff=" \Num:=big - n;
        n := 4194304 * 2;
        IF n = big TPWrite "mul exact";
        n := big DIV 2;
        IF n = 4194304 TPWrite "div exact";
        n := 8388607 + 1;
        IF n = big TPWrite "add exact";
        TPWrite "mod=" \Num:=8388607 MOD 10;
        FOR i FROM 1 TO 1000 DO
            sum := sum + i;
        ENDFOR
        IF sum = 500500 TPWrite "sum exact";
        TPWrite "sum mod 1000=" \Num:=sum MOD 1000;
    ENDPROC
ENDMODULE
