MODULE err_divzero_mod
    ! MOD by zero, unhandled.
    PROC main()
        VAR num zero := 0;
        VAR num x;
        TPWrite "start";
        x := 10 MOD zero;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
