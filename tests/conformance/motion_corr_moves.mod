MODULE motion_corr_moves
    ! \Corr on MoveL, MoveC and TriggL: each follows its path shifted by the total
    ! correction, in the path coordinate system (x along the path, z the tool's z axis,
    ! y = z × x; corr.rs, uncertain). The tool points down ([0,0,1,0]: tool z = -z of
    ! the world), so a correction of 10 along path z lowers the TCP 10 mm whichever
    ! way the path goes: CRobT at each stop point reads z = 390. A move without \Corr
    ! goes back to its programmed point (z = 400).
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR corrdescr c;
    VAR triggdata t;
    VAR intnum mark;
    PROC main()
        VAR robtarget p;
        MoveJ p0, v1000, fine, tool0;
        CorrCon c;
        CorrWrite c, [0, 0, 10];
        MoveL Offs(p0, 100, 0, 0), v200, fine, tool0 \Corr;
        p := CRobT();
        TPWrite "MoveL " \Pos:=p.trans;
        MoveC Offs(p0, 50, 50, 0), p0, v200, fine, tool0 \Corr;
        p := CRobT();
        TPWrite "MoveC " \Pos:=p.trans;
        CONNECT mark WITH on_mark;
        ! The interrupt comes when the robot stands at the point, before the stop
        ! point's settle time lets the program go on.
        TriggInt t, 0, mark;
        TriggL Offs(p0, 0, 100, 0), v200, t, fine, tool0 \Corr;
        p := CRobT();
        TPWrite "TriggL " \Pos:=p.trans;
        MoveL p0, v200, fine, tool0;
        p := CRobT();
        TPWrite "MoveL " \Pos:=p.trans;
    ENDPROC
    TRAP on_mark
        TPWrite "trigger";
    ENDTRAP
ENDMODULE
