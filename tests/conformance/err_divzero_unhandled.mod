MODULE err_divzero_unhandled
    ! No ERROR handler anywhere: the system error handler reports the error
    ! and stops execution (manual 1.12).
    PROC main()
        VAR num zero := 0;
        VAR num x;
        TPWrite "start";
        x := 10 / zero;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
