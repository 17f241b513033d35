MODULE undo_ignores_return
    ! Manual 1.13: an UNDO handler must not contain RETURN; there it is ignored with
    ! an event-log warning, and the handler goes on (in a FUNC's UNDO handler too:
    ! its value is not even evaluated). A RETURN in a routine the handler calls
    ! still ends that routine (helper does not print "helper 2") and a FUNC's
    ! RETURN still gives its value: it only goes back to its caller inside the same
    ! UNDO, so it cannot cut the UNDO short (our reading, docs/semantics.md UNDO),
    ! and it logs nothing: the log goes from the two warnings straight to the end.
    VAR num r;

    PROC helper(bool early)
        TPWrite "helper 1";
        IF early RETURN;
        TPWrite "helper 2";
    ENDPROC

    FUNC num twice(num x)
        RETURN 2 * x;
    ENDFUNC

    FUNC num compute()
        TPWrite "compute";
        EXIT;
        RETURN 1;
    UNDO
        TPWrite "undo compute 1";
        RETURN 9;
        TPWrite "undo compute 2";
    ENDFUNC

    PROC work()
        r := compute();
    UNDO
        TPWrite "undo work 1";
        RETURN;
        TPWrite "undo work 2";
        helper TRUE;
        TPWrite "twice " \Num:=twice(21);
        TPWrite "undo work 3";
    ENDPROC

    PROC main()
        work;
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
