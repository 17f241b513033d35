MODULE recover_nested_handlers
    ! Each routine in a chain may have its own handler; the innermost one
    ! with a handler gets the error first.
    VAR num zero := 0;

    PROC inner()
        VAR num x;
        x := 1 / zero;
        TPWrite "inner after";
    ERROR
        TPWrite "inner handler";
        TRYNEXT;
    ENDPROC

    PROC outer()
        inner;
        RAISE 3;
        TPWrite "outer after";
    ERROR
        TPWrite "outer handler errno=" \Num:=ERRNO;
        TRYNEXT;
    ENDPROC

    PROC main()
        outer;
        TPWrite "main end";
    ERROR
        TPWrite "main handler must not run";
        TRYNEXT;
    ENDPROC
ENDMODULE
