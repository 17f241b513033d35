MODULE undo_manual_example
    ! The UNDO example of manual 1.13; its output is given there line by
    ! line. EXIT starts UNDO: the handlers of the current call chain run from
    ! the innermost (B) to main. A has no UNDO handler.
    PROC B()
        TPWrite "In Routine B";
        Exit;
    UNDO
        TPWrite "In UNDO of routine B";
    ENDPROC

    PROC A()
        TPWrite "In Routine A";
        B;
    ENDPROC

    PROC main()
        TPWrite "In main";
        A;
    UNDO
        TPWrite "In UNDO of main";
    ENDPROC
ENDMODULE
