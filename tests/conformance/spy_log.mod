MODULE spy_log
    ! SpyStart logs every statement executed until SpyStop, one line each: the task,
    ! the statement as written, the time in and out (ms since SpyStart on the
    ! controller clock) and READY / WAIT / ERROR (layout: docs/semantics.md, ours).
    ! A call's line follows the lines of the routine it called. The log is read back.
    VAR iodev log;
    VAR num r;

    PROC sub()
        r := 2;
    ENDPROC

    PROC main()
        SpyStart "HOME:/spy.log";
        r := 1;
        WaitTime 0.5;
        sub;
        SpyStop;
        Open "HOME:/spy.log", log \Read;
        FOR i FROM 1 TO 5 DO
            TPWrite ReadStr(log);
        ENDFOR
        TPWrite "end: " + ReadStr(log);
        Close log;
    ENDPROC
ENDMODULE
