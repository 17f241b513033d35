MODULE recover_illraise_handled
    ! RAISE 1 and RAISE 90 are valid user errors; RAISE 91 and RAISE 0 set
    ! ERRNO to ERR_ILLRAISE, which the handler can catch (semantics 1.1).
    PROC tryRaise(num e)
        RAISE e;
    ERROR
        IF ERRNO = ERR_ILLRAISE THEN
            TPWrite "illegal " \Num:=e;
        ELSE
            TPWrite "errno=" \Num:=ERRNO;
        ENDIF
        RETURN;
    ENDPROC

    PROC main()
        tryRaise 1;
        tryRaise 90;
        tryRaise 91;
        tryRaise 0;
    ENDPROC
ENDMODULE
