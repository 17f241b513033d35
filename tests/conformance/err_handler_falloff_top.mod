MODULE err_handler_falloff_top
    ! A handler that ends without RETRY, TRYNEXT, RETURN or RAISE: reaching
    ! the end of the handler calls the system error handler (manual 1.12),
    ! which stops execution. (In main both readings of falling off agree.)
    PROC main()
        VAR num zero := 0;
        VAR num x;
        x := 1 / zero;
        TPWrite "not reached";
    ERROR
        TPWrite "handling";
    ENDPROC
ENDMODULE
