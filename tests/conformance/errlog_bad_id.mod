MODULE errlog_bad_id
    ! ErrLog event numbers run from 4800 to 4999; 4700 is an argument error.
    PROC main()
        ErrLog 4700, "Out of range", ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED, ERRSTR_UNUSED;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "bad id";
        RETURN;
    ENDPROC
ENDMODULE
