MODULE motion_calc_stat_no_wobj
    ! CalcRobT and CalcJointT compute in wobj0 when \WObj is omitted; with a stationary
    ! tool the manual asks for \WObj (the work object the robot holds): without it
    ! execution stops. With it, the TCP is at pA = [0,-50,0] in the held object.
    PERS tooldata tStat := [FALSE,[[400,0,250],[0,0,1,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
    PERS wobjdata wHeld := [TRUE,TRUE,"",[[0,0,100],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    CONST robtarget pA := [[0,-50,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR robtarget seen;

    PROC main()
        ConfJ \Off;
        MoveJ pA, v500, fine, tStat \WObj:=wHeld;
        seen := CalcRobT(CJointT(), tStat \WObj:=wHeld);
        TPWrite "held " \Pos:=seen.trans;
        seen := CalcRobT(CJointT(), tStat);
        TPWrite "not reached";
    ENDPROC
ENDMODULE
