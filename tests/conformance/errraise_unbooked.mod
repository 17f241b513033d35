MODULE errraise_unbooked
    ! ErrRaise needs an errnum that BookErrNo booked: ERR_LATE still holds -1, so the
    ! instruction fails with an argument error, which the handler sees.
    VAR errnum ERR_LATE := -1;

    PROC main()
        ErrRaise "ERR_LATE", 4801, "Too late", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "not booked";
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
