MODULE motion_readback_stat_active
    ! CRobT with \Tool and no \WObj reads in the active work object: here the one the
    ! robot holds past a stationary tool (as in motion_stationary_tool), so the TCP is
    ! at pA = [0,-50,0] in it. A tool the robot holds cannot read in a work object the
    ! robot holds too: execution stops.
    PERS tooldata tStat := [FALSE,[[400,0,250],[0,0,1,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
    PERS wobjdata wHeld := [TRUE,TRUE,"",[[0,0,100],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    CONST robtarget pA := [[0,-50,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR robtarget seen;

    PROC main()
        ConfJ \Off;
        MoveJ pA, v500, fine, tStat \WObj:=wHeld;
        seen := CRobT(\Tool:=tStat);
        TPWrite "active " \Pos:=seen.trans;
        seen := CRobT(\Tool:=tool0);
        TPWrite "not reached";
    ENDPROC
ENDMODULE
