MODULE motion_readback_active_wobj
    ! CRobT and CPos without \WObj read in the active work object (the last move's),
    ! also when \Tool is given; CalcRobT without \WObj computes in wobj0.
    ! wobj1's user frame is 100 mm along the world x axis: (250, 0, 400) in it is
    ! (350, 0, 400) in the world.
    PERS wobjdata wobj1 := [FALSE, TRUE, "", [[100,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];
    CONST robtarget p := [[250,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        VAR robtarget r;
        MoveJ p, v1000, fine, tool0 \WObj:=wobj1;
        r := CRobT(\Tool:=tool0);
        TPWrite "CRobT tool " \Pos:=r.trans;
        TPWrite "CPos tool " \Pos:=CPos(\Tool:=tool0);
        r := CRobT(\Tool:=tool0 \WObj:=wobj0);
        TPWrite "CRobT wobj0 " \Pos:=r.trans;
        r := CalcRobT(CJointT(), tool0);
        TPWrite "CalcRobT " \Pos:=r.trans;
    ENDPROC
ENDMODULE
