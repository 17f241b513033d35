MODULE recover_raise_new_in_handler
    ! RAISE with a new number in a handler passes that error to the caller's
    ! handler (manual 1.12: RAISE calls the caller's error handler).
    PROC sub()
        VAR num zero := 0;
        VAR num x;
        x := 1 / zero;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "sub converts the error";
            RAISE 20;
        ENDIF
    ENDPROC

    PROC main()
        sub;
        TPWrite "main goes on";
    ERROR
        TPWrite "main errno=" \Num:=ERRNO;
        TRYNEXT;
    ENDPROC
ENDMODULE
