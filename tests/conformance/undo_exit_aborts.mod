MODULE undo_exit_aborts
    ! Manual 1.13: "EXIT aborts UNDO like a run error or a stop: the rest of the
    ! UNDO handlers are ignored", and an UNDO cut short leaves an event-log warning
    ! (docs/elog.md 40902). ExitCycle starts the UNDO (continuous run, `--cycles 3`);
    ! the EXIT in inner's handler ends it there: neither the rest of that handler
    ! nor mid's and main's handlers run, and EXIT ends the program, so no second
    ! cycle starts (EXIT: no restart, 1.5).
    VAR num cycle := 0;

    PROC inner()
        TPWrite "inner";
        ExitCycle;
    UNDO
        TPWrite "undo inner 1";
        EXIT;
        TPWrite "undo inner 2";
    ENDPROC

    PROC mid()
        inner;
    UNDO
        TPWrite "undo mid";
    ENDPROC

    PROC main()
        cycle := cycle + 1;
        TPWrite "cycle " \Num:=cycle;
        mid;
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
