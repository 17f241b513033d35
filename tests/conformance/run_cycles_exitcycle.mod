MODULE run_cycles_exitcycle
    ! Continuous run mode (`--cycles 2`): ExitCycle ends the first cycle and the second
    ! starts at main, the variables keeping their values (ExitCycle). The robot's
    ! movement stops at ExitCycle and its path is cleared: the MoveL \Conc begun at
    ! 0 s is 29.5 mm along at 0.3 s (0.5 mm ramp + 0.29 s * 100 mm/s, as in
    ! motion_path_store), and the robot stays there. In the second cycle main runs to
    ! its end, which ends the run after two cycles.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR num cycle := 0;
    VAR clock c;

    PROC main()
        VAR robtarget here;
        cycle := cycle + 1;
        TPWrite "cycle " \Num:=cycle;
        IF cycle = 1 THEN
            TPWrite "continuous " \Bool:=RunMode() = RUN_CONT_CYCLE;
            MoveJ p0, v1000, fine, tool0;
            ClkStart c;
            MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
            WaitTime 0.3;
            ExitCycle;
        ENDIF
        WaitTime 1;
        here := CRobT(\Tool:=tool0);
        TPWrite "x " \Num:=here.trans.x;
        TPWrite "after " + NumToStr(ClkRead(c), 2);
    ENDPROC
ENDMODULE
