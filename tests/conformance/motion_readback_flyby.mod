MODULE motion_readback_flyby
    ! CRobT while the robot is on a fly-by move that still waits for its successor
    ! (the program is in WaitTime): the robot is where its motion has taken it.
    ! Worked by hand: 200 mm at v100 (10 m/s² path acceleration): 0.01 s to reach
    ! 100 mm/s over 0.5 mm, then 100 mm/s; 1 s after the start it has gone
    ! 0.5 + 0.99 · 100 = 99.5 mm: y = -100 + 99.5 = -0.5.
    CONST robtarget p0 := [[300,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR intnum tick;
    VAR robtarget here;

    PROC main()
        ConfL \Off;
        MoveL p0, v500, fine, tool0;
        CONNECT tick WITH look;
        ITimer \Single, 1, tick;
        MoveL Offs(p0, 0, 200, 0), v100, z10, tool0;
        WaitTime 3;
    ENDPROC

    TRAP look
        here := CRobT(\Tool:=tool0);
        TPWrite "y " \Num:=Round(here.trans.y \Dec:=1);
    ENDTRAP
ENDMODULE
