MODULE err_divzero_in_sub
    ! The error in a routine without handler propagates to the callers; none
    ! has a handler, so the system error handler stops execution (manual 1.12).
    PROC inner(num d)
        VAR num x;
        TPWrite "inner";
        x := 1 / d;
        TPWrite "inner after";
    ENDPROC

    PROC outer()
        inner 0;
        TPWrite "outer after";
    ENDPROC

    PROC main()
        TPWrite "main";
        outer;
        TPWrite "main after";
    ENDPROC
ENDMODULE
