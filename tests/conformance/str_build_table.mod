MODULE str_build_table
    ! Strings assembled in a loop from parts; ValToStr of integers.
    PROC main()
        VAR string line;
        FOR row FROM 1 TO 3 DO
            line := "row" + ValToStr(row) + ":";
            FOR col FROM 1 TO 3 DO
                line := line + " " + ValToStr(row * col);
            ENDFOR
            TPWrite line;
        ENDFOR
    ENDPROC
ENDMODULE
