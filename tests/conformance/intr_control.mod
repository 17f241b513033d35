MODULE intr_control
    ! manual 1.11: \Single fires once; an interrupt asleep (ISleep) drops its events
    ! until IWatch; while interrupts are disabled (IDisable) they queue and their traps
    ! run after IEnable, before the next instruction. CONNECT on a connected intnum
    ! raises ERR_ALRDYCNT; an intnum never connected is unknown (ERR_UNKINO).
    VAR intnum t1;
    VAR intnum t2;
    VAR num fired := 0;

    PROC main()
        CONNECT t1 WITH count_trap;
        ITimer \Single, 0.5, t1;
        WaitTime 1;
        TPWrite "single " \Num:=fired;
        IDelete t1;
        CONNECT t1 WITH count_trap;
        ITimer 1, t1;
        ISleep t1;
        WaitTime 1.5;
        TPWrite "asleep " \Num:=fired;
        IWatch t1;
        IDisable;
        WaitTime 1;
        TPWrite "disabled " \Num:=fired;
        IEnable;
        TPWrite "enabled " \Num:=fired;
        CONNECT t1 WITH count_trap;
        IDelete t1;
        ISleep t2;
        TPWrite "end " \Num:=fired;
    ERROR
        IF ERRNO = ERR_ALRDYCNT TPWrite "ERR_ALRDYCNT";
        IF ERRNO = ERR_UNKINO TPWrite "ERR_UNKINO";
        TRYNEXT;
    ENDPROC

    TRAP count_trap
        fired := fired + 1;
    ENDTRAP
ENDMODULE
