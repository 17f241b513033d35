MODULE recover_retry_call
    ! When the error came out of a called routine, RETRY in the caller runs
    ! the whole call again.
    VAR num zero := 0;

    PROC level3()
        VAR num x;
        TPWrite "level3";
        x := 6 / zero;
        TPWrite "level3 ok";
    ENDPROC

    PROC level2()
        TPWrite "level2";
        level3;
    ENDPROC

    PROC main()
        level2;
        TPWrite "main end";
    ERROR
        TPWrite "main handler";
        zero := 3;
        RETRY;
    ENDPROC
ENDMODULE
