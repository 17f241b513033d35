MODULE err_in_handler
    ! An error inside an ERROR handler cannot be recovered: it goes to the
    ! system error handler (manual 1.12), even though main has a handler.
    VAR num zero := 0;

    PROC sub()
        VAR num x;
        x := 1 / zero;
    ERROR
        TPWrite "sub handler";
        x := 2 / zero;
        TPWrite "not reached";
        TRYNEXT;
    ENDPROC

    PROC main()
        sub;
        TPWrite "not reached";
    ERROR
        TPWrite "main handler must not run";
        TRYNEXT;
    ENDPROC
ENDMODULE
