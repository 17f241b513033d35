MODULE err_signal_not_connected
    ! A signal variable declared in RAPID and never connected with AliasIO raises
    ! ERR_NO_ALIASIO_DEF when it is read (manual 1.9, reading input and output signals).
    VAR signaldi di_part;

    PROC main()
        TPWrite "before";
        IF di_part = 1 TPWrite "not reached";
        TPWrite "not reached either";
    ENDPROC
ENDMODULE
