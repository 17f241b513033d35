MODULE undo_ignores_break
    ! Manual 1.13: BREAK (the debugging stop, 1.5) in UNDO context is ignored with
    ! an event-log warning, in the handler and in a routine it calls; the rest of
    ! the handler and the caller's UNDO handler run. Break inside a loop ends the
    ! loop (RW 6.15, 1.5), which stops nothing: it works in UNDO as elsewhere and
    ! logs nothing.
    VAR num n := 0;

    PROC cleanup()
        TPWrite "cleanup 1";
        Break;
        TPWrite "cleanup 2";
    ENDPROC

    PROC work()
        TPWrite "work";
        EXIT;
    UNDO
        TPWrite "undo work 1";
        Break;
        WHILE TRUE DO
            n := n + 1;
            IF n = 3 Break;
        ENDWHILE
        TPWrite "loop ended at " \Num:=n;
        cleanup;
        TPWrite "undo work 2";
    ENDPROC

    PROC main()
        work;
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
