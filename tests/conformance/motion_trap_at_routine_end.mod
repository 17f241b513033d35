MODULE motion_trap_at_routine_end
    ! Manual 1.11 and 2.3: a stop point makes the program wait until the robot stands
    ! there, and interrupts are served meanwhile. The move below is main's last
    ! instruction: the timer's trap still runs at 0.3 s, while the robot moves (the
    ! 100 mm at v100 take 1.06 s), before main ends.
    VAR intnum tick;
    VAR clock c;

    PROC main()
        ConfL \Off;
        ClkStart c;
        CONNECT tick WITH OnTick;
        ITimer \Single, 0.3, tick;
        MoveL [[374,0,530],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
    ENDPROC

    TRAP OnTick
        TPWrite "trap at " \Num:=ClkRead(c);
    ENDTRAP
ENDMODULE
