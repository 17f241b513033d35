MODULE test_expressions
    ! TEST on an expression, CASE values given by constants and expressions.
    CONST num RED := 0;
    CONST num GREEN := 1;

    PROC main()
        VAR string s := "";
        FOR i FROM 1 TO 6 DO
            TEST i MOD 3
            CASE RED:
                s := s + "r";
            CASE GREEN:
                s := s + "g";
            CASE GREEN + 1:
                s := s + "b";
            ENDTEST
        ENDFOR
        TPWrite s;
    ENDPROC
ENDMODULE
