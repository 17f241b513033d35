MODULE errraise_unhandled
    ! A booked error raised by ErrRaise that no handler takes stops the program
    ! (system error handler); the message names the errnum and the title.
    VAR errnum ERR_GRIP := -1;

    PROC main()
        BookErrNo ERR_GRIP;
        TPWrite "before";
        ErrRaise "ERR_GRIP", 4800, "Gripper open", ERRSTR_EMPTY, ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
