MODULE Monitor
    ! T_MONITOR: a background task (it runs only while T_ROB1 waits) that reports
    ! the cell's state every second from a timer interrupt.
    PERS num partsDone := 0;
    VAR intnum tick;

    PROC monitor_main()
        CONNECT tick WITH report;
        ITimer 1, tick;
        WHILE TRUE DO
            WaitTime 10;
        ENDWHILE
    ENDPROC

    TRAP report
        VAR string press := "open";
        IF doPressClose = 1 press := "closed";
        TPWrite "monitor: " + NumToStr(partsDone, 0) + " parts done, press " + press;
    ENDTRAP
ENDMODULE
