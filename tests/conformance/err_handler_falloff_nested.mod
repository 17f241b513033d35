MODULE err_handler_falloff_nested
    ! Manual 1.12 (system error handler): "when the end of any error handler
    ! is reached within the call chain, the system error handler is called".
    ! So sub's handler falling off its end stops execution; the error is NOT
    ! passed on to main's handler. (semantics 1.1 guesses "like RAISE" with
    ! (?); the spec wins.)
    PROC sub()
        VAR num zero := 0;
        VAR num x;
        x := 1 / zero;
    ERROR
        TPWrite "sub handler falls off";
    ENDPROC

    PROC main()
        sub;
        TPWrite "not reached";
    ERROR
        TPWrite "main handler";
        TRYNEXT;
    ENDPROC
ENDMODULE
