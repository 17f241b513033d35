MODULE recover_retry_fix
    ! RETRY runs the statement that caused the error again (manual 1.12).
    PROC main()
        VAR num divisor := 0;
        VAR num r;
        r := 12 / divisor;
        TPWrite "r=" \Num:=r;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "fixing divisor";
            divisor := 4;
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
