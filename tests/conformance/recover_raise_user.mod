MODULE recover_raise_user
    ! RAISE with a user number 1..90 (manual 1.12, errors raised by the
    ! program); ERRNO holds the number in the handler.
    CONST errnum ERR_PART := 12;

    PROC main()
        TPWrite "raising";
        RAISE 10;
        TPWrite "after first";
        RAISE ERR_PART;
        TPWrite "after second";
    ERROR
        IF ERRNO = ERR_PART THEN
            TPWrite "part error";
        ELSE
            TPWrite "errno=" \Num:=ERRNO;
        ENDIF
        TRYNEXT;
    ENDPROC
ENDMODULE
