MODULE err_trap_unhandled
    ! An error in a TRAP routine without an ERROR handler goes to the system error
    ! handler (manual 1.12: errors in traps), not to the interrupted routine's handler.
    VAR intnum tick;
    VAR num zero := 0;
    VAR num x;

    PROC main()
        CONNECT tick WITH bad_trap;
        ITimer \Single, 0.5, tick;
        WaitTime 1;
        TPWrite "not reached";
    ERROR
        TPWrite "not reached either";
        RETURN;
    ENDPROC

    TRAP bad_trap
        TPWrite "trap";
        x := 1 / zero;
    ENDTRAP
ENDMODULE
