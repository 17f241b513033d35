MODULE err_undo_run_error
    ! Manual 1.13: a run error while an UNDO handler runs stops the program (the
    ! system error handler, 1.12): the rest of the handler is not run, nor the
    ! UNDO handlers still waiting in the call chain (main's), and an event-log
    ! warning says the UNDO was cut short (docs/elog.md 40902). The error comes
    ! from a routine the handler calls, which is in UNDO context too.
    VAR num zero := 0;
    VAR num x;

    PROC cleanup()
        TPWrite "cleanup 1";
        x := 1 / zero;
        TPWrite "cleanup 2";
    ENDPROC

    PROC work()
        TPWrite "work";
        EXIT;
    UNDO
        TPWrite "undo work 1";
        cleanup;
        TPWrite "undo work 2";
    ENDPROC

    PROC main()
        work;
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
