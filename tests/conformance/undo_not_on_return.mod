MODULE undo_not_on_return
    ! UNDO does not run when a routine returns normally, at its end or by
    ! RETURN (manual 1.13), nor when main ends normally.
    PROC a()
        TPWrite "in a";
    UNDO
        TPWrite "undo a";
    ENDPROC

    PROC b()
        TPWrite "in b";
        RETURN;
    UNDO
        TPWrite "undo b";
    ENDPROC

    PROC main()
        a;
        b;
        TPWrite "main end";
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
