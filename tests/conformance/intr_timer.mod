MODULE intr_timer
    ! ITimer 1 fires every second of controller time; its trap runs during the wait
    ! (manual 1.11: traps run between instructions and during waits) and the wait then
    ! goes on for the rest of its time. IDelete stops the interrupt.
    VAR intnum tick;
    VAR num count := 0;
    VAR clock c;

    PROC main()
        ClkStart c;
        CONNECT tick WITH on_tick;
        ITimer 1, tick;
        WaitTime 3.5;
        TPWrite "ticks " \Num:=count;
        TPWrite "waited until " \Num:=ClkRead(c);
        IDelete tick;
        WaitTime 2;
        TPWrite "after IDelete " \Num:=count;
    ENDPROC

    TRAP on_tick
        count := count + 1;
        TPWrite "tick " \Num:=count;
        TPWrite "  at " \Num:=ClkRead(c);
        TPWrite "  INTNO is the tick " \Bool:=INTNO = tick;
    ENDTRAP
ENDMODULE
