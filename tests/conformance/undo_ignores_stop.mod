MODULE undo_ignores_stop
    ! Manual 1.13: an UNDO handler must not contain STOP; used in UNDO context (the
    ! handler, and any routine it calls: "the current routine is part of a call
    ! chain starting in an UNDO handler") it is ignored and an event-log warning is
    ! written. So Stop, also with a switch, halts nothing here: the rest of work's
    ! UNDO handler runs, then main's (innermost first, 1.13), and the run ends
    ! normally. The warnings name the routine each Stop was in (docs/elog.md 40901).
    PROC cleanup()
        TPWrite "cleanup 1";
        Stop \NoRegain;
        TPWrite "cleanup 2";
    ENDPROC

    PROC work()
        TPWrite "work";
        EXIT;
        TPWrite "not reached";
    UNDO
        TPWrite "undo work 1";
        Stop;
        TPWrite "undo work 2";
        cleanup;
        TPWrite "undo work 3";
    ENDPROC

    PROC main()
        work;
        TPWrite "not reached";
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
