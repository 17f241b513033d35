MODULE if_nested_blocks
    ! Nested IF blocks; an IF without ELSE whose condition is FALSE does nothing.
    PROC grade(num score, bool bonus)
        IF score >= 50 THEN
            IF bonus THEN
                TPWrite "pass with bonus";
            ELSE
                TPWrite "pass";
            ENDIF
        ELSE
            IF score >= 40 THEN
                TPWrite "near miss";
            ENDIF
            TPWrite "fail";
        ENDIF
    ENDPROC

    PROC main()
        grade 80, TRUE;
        grade 50, FALSE;
        grade 45, TRUE;
        grade 10, FALSE;
        IF FALSE THEN
            TPWrite "never";
        ENDIF
        TPWrite "end";
    ENDPROC
ENDMODULE
