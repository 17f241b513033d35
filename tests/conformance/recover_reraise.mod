MODULE recover_reraise
    ! RAISE without a number in a handler propagates the same error to the
    ! caller, at the point of the call (manual 1.12).
    PROC check(num v)
        IF v < 0 RAISE 5;
        TPWrite "ok " \Num:=v;
    ERROR
        TPWrite "check handler errno=" \Num:=ERRNO;
        RAISE;
    ENDPROC

    PROC main()
        VAR num bad := -1;
        check 1;
        check bad;
        TPWrite "after";
    ERROR
        TPWrite "main handler errno=" \Num:=ERRNO;
        TRYNEXT;
    ENDPROC
ENDMODULE
