MODULE for_nested_table
    ! Nested FOR loops with independent loop variables.
    PROC main()
        VAR string line;
        FOR i FROM 1 TO 3 DO
            line := "";
            FOR j FROM 1 TO 4 DO
                line := line + ValToStr(i * j) + " ";
            ENDFOR
            TPWrite line + "|";
        ENDFOR
    ENDPROC
ENDMODULE
