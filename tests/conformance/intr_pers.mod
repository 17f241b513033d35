MODULE intr_pers
    ! IPers (manual 1.11): an interrupt each time the persistent gets another value;
    ! writing the value it already has is no change. The trap runs before the next
    ! instruction. After IDelete nothing fires.
    PERS num level := 0;
    VAR intnum watch;

    PROC main()
        CONNECT watch WITH level_trap;
        IPers level, watch;
        level := 5;
        TPWrite "after 5";
        level := 5;
        TPWrite "after 5 again";
        level := 7;
        TPWrite "after 7";
        IDelete watch;
        level := 9;
        TPWrite "after 9";
    ENDPROC

    TRAP level_trap
        TPWrite "level now " \Num:=level;
    ENDTRAP
ENDMODULE
