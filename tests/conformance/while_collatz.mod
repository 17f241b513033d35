MODULE while_collatz
    ! Collatz sequence from 6.
    PROC main()
        VAR num n := 6;
        VAR num steps := 0;
        VAR string s;
        s := ValToStr(n);
        WHILE n <> 1 DO
            IF n MOD 2 = 0 THEN
                n := n DIV 2;
            ELSE
                n := 3 * n + 1;
            ENDIF
            steps := steps + 1;
            s := s + " " + ValToStr(n);
        ENDWHILE
        TPWrite s;
        TPWrite "steps=" \Num:=steps;
    ENDPROC
ENDMODULE
