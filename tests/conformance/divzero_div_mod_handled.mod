MODULE divzero_div_mod_handled
    ! /, DIV and MOD by zero all raise ERR_DIVZERO (semantics 1.3, 2.1).
    PROC main()
        VAR num zero := 0;
        VAR num x := 0;
        VAR num caught := 0;
        x := 5 DIV zero;
        x := 5 MOD zero;
        x := 5 / zero;
        TPWrite "caught=" \Num:=caught;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            Incr caught;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
