MODULE err_late_unknown
    ! ERR_REFUNKPRC with no handler stops execution.
    PROC known()
        TPWrite "known";
    ENDPROC

    PROC main()
        VAR string name := "known";
        % name %;
        name := "unknown";
        % name %;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
