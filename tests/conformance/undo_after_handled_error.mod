MODULE undo_after_handled_error
    ! A handled error does not start UNDO; a later EXIT does. A routine may
    ! have both an ERROR and an UNDO handler (manual 1.1.5 syntax).
    PROC job()
        VAR num zero := 0;
        VAR num x;
        x := 1 / zero;
        TPWrite "job continues";
        EXIT;
    ERROR
        TPWrite "job handler";
        TRYNEXT;
    UNDO
        TPWrite "undo job";
    ENDPROC

    PROC main()
        job;
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
