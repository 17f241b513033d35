MODULE undo_ignores_raise
    ! Manual 1.13: RAISE in UNDO context is ignored with an event-log warning, in
    ! the handler and in a routine it calls; it raises nothing, so no ERROR handler
    ! runs and the program is not stopped: the rest of the handler and the caller's
    ! UNDO handler run. Here the UNDO runs because ExitCycle ends the first cycle of
    ! a continuous run (`--cycles 2`, ExitCycle: the cycle ends, UNDO handlers run,
    ! 1.13 "program reset"); the second cycle then runs main to its end.
    VAR num cycle := 0;

    PROC cleanup()
        TPWrite "cleanup 1";
        RAISE 7;
        TPWrite "cleanup 2";
    ERROR
        TPWrite "cleanup ERROR handler";
    ENDPROC

    PROC work()
        TPWrite "work";
        ExitCycle;
    UNDO
        TPWrite "undo work 1";
        RAISE 5;
        TPWrite "undo work 2";
        cleanup;
        TPWrite "undo work 3";
    ENDPROC

    PROC main()
        cycle := cycle + 1;
        TPWrite "cycle " \Num:=cycle;
        IF cycle = 1 work;
        TPWrite "end of main";
    ERROR
        TPWrite "main ERROR handler";
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
