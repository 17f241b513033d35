MODULE for_zero_iterations
    ! With an explicit STEP whose sign does not lead from From to To the
    ! body never runs.
    PROC main()
        VAR num count := 0;
        FOR i FROM 1 TO 0 STEP 1 DO
            count := count + 1;
        ENDFOR
        FOR i FROM 5 TO 10 STEP -1 DO
            count := count + 1;
        ENDFOR
        TPWrite "count=" \Num:=count;
    ENDPROC
ENDMODULE
