MODULE err_reraise_unhandled
    ! A handler that re-raises to a caller without handler: the error reaches
    ! the top of the call chain and the system error handler (manual 1.12).
    PROC sub()
        VAR num zero := 0;
        VAR num x;
        x := 1 / zero;
    ERROR
        TPWrite "sub saw the error";
        RAISE;
    ENDPROC

    PROC main()
        sub;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
