MODULE intr_waituntil_trap
    ! Traps run while WaitUntil waits (§1.11), and the condition sees what they change:
    ! the timer's trap counts at 0.45, 0.9 and 1.35 s; the next poll after the third
    ! (WaitUntil polls every 0.1 s) ends the wait at 1.4 s. A single timer's trap at
    ! 0.25 s ends a wait without \MaxTime the same way, at the poll of 0.3 s.
    VAR intnum ticker;
    VAR intnum once;
    VAR num ticks := 0;
    VAR bool ready := FALSE;
    VAR clock c;

    TRAP tick
        ticks := ticks + 1;
    ENDTRAP

    TRAP ready_now
        ready := TRUE;
    ENDTRAP

    PROC main()
        CONNECT ticker WITH tick;
        ITimer 0.45, ticker;
        ClkStart c;
        WaitUntil ticks >= 3 \MaxTime:=10;
        TPWrite "ticks " \Num:=ticks;
        TPWrite "waited " \Num:=ClkRead(c);
        IDelete ticker;
        CONNECT once WITH ready_now;
        ITimer \Single, 0.25, once;
        ClkStop c;
        ClkReset c;
        ClkStart c;
        WaitUntil ready;
        TPWrite "ready after " \Num:=ClkRead(c);
    ENDPROC
ENDMODULE
