MODULE waituntil_poll_and_timeout
    ! WaitUntil re-evaluates its condition every poll (here every 0.25 s of
    ! controller time); \MaxTime with \TimeFlag sets the flag and goes on; without
    ! \TimeFlag the timeout is ERR_WAIT_MAXTIME (§1.6, semantics.md 3.4).
    VAR clock c;
    PROC main()
        VAR bool late;
        ClkReset c;
        ClkStart c;
        WaitUntil ClkRead(c) >= 1 \PollRate:=0.25;
        TPWrite "reached at " \Num:=ClkRead(c);
        WaitUntil TRUE \MaxTime:=5 \TimeFlag:=late;
        TPWrite "at once, late=" \Bool:=late;
        WaitUntil FALSE \MaxTime:=0.5 \TimeFlag:=late \PollRate:=0.25;
        TPWrite "gave up, late=" \Bool:=late;
        TPWrite "clock " \Num:=ClkRead(c);
        WaitUntil FALSE \MaxTime:=0.5 \PollRate:=0.25;
        TPWrite "after the timeout";
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            TPWrite "timeout " \Num:=ClkRead(c);
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
