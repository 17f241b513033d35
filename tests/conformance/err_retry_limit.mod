MODULE err_retry_limit
    ! A statement that always fails: after 4 RETRYs the error is no longer
    ! recovered and execution stops (manual 1.12; semantics 1.1 limit 4).
    ! The failing statement runs 1 + 4 = 5 times. The handler prints nothing,
    ! so the output does not depend on whether the handler is entered a
    ! fifth time; the errno reported (ERR_DIVZERO or ERR_EXCRTYMAX) is not
    ! checked.
    VAR num execs := 0;

    FUNC num zeroTick()
        execs := execs + 1;
        TPWrite "try " \Num:=execs;
        RETURN 0;
    ENDFUNC

    PROC main()
        VAR num r;
        r := 10 / zeroTick();
        TPWrite "not reached";
    ERROR
        RETRY;
    ENDPROC
ENDMODULE
