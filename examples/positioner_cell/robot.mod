MODULE robot
    !-----------------------------------------------------------------
    ! T_ROB1 works on the part that turntable STN1 of task T_STN1 carries.
    ! wobjTable rides the table (ufprog FALSE, ufmec "STN1"); its points
    ! are on the part, wherever the table has turned it.
    !-----------------------------------------------------------------

    PERS tasks tCell{2} := [["T_ROB1"],["T_STN1"]];
    VAR syncident sTurn;
    VAR syncident sTurned;
    VAR syncident sWeld;
    VAR syncident sWelded;

    PERS wobjdata wobjTable := [FALSE,FALSE,"STN1",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    ! Above the part's edge with the table at 0°: 100 mm from the table's axis.
    CONST robtarget pHome := [[300,0,450],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! On the part: a tack point on its edge and 50 mm above it, torch pointing down.
    CONST robtarget pTackA := [[-100,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pAboveA := [[-100,0,250],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! The same points turned half a turn about the torch (q [0,1,0,0]): with the part
    ! turned half a turn, the torch keeps its angle in the world.
    CONST robtarget pTackB := [[-100,0,200],[0,1,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pAboveB := [[-100,0,250],[0,1,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! The weld seam's end, 50 mm along the rim from pTackB.
    CONST robtarget pSeamEnd := [[-100,50,200],[0,1,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR clock cycle;

    PROC main()
        ConfL \Off;
        Reset doTack;
        Reset doArc;
        MoveJ pHome, v1000, fine, tool0;
        ClkStart cycle;
        ! Side A, the table standing at 0°.
        Tack pTackA, pAboveA, v100;
        ! The table turns the part half a turn while the robot stands clear of it.
        WaitSyncTask sTurn, tCell;
        WaitSyncTask sTurned, tCell;
        ! Side B: the tack point on the other edge, where the table has it now.
        MoveL pAboveB, v200, fine, tool0 \WObj:=wobjTable;
        Tack pTackB, pAboveB, v200;
        ! The seam along the rim, welded while the table turns back.
        MoveL pTackB, v100, fine, tool0 \WObj:=wobjTable;
        SyncMoveOn sWeld, tCell;
        SetDO doArc, 1;
        MoveL pSeamEnd \ID:=10, v20, fine, tool0 \WObj:=wobjTable;
        SetDO doArc, 0;
        SyncMoveOff sWelded;
        ClkStop cycle;
        TPWrite "Part done in " \Num:=ClkRead(cycle);
    ENDPROC

    ! A tack at pAt, from and back to pOver at `speed`.
    PROC Tack(robtarget pAt, robtarget pOver, speeddata speed)
        MoveL pAt, speed, fine, tool0 \WObj:=wobjTable;
        PulseDO \PLength:=0.2, doTack;
        WaitTime 0.2;
        MoveL pOver, speed, fine, tool0 \WObj:=wobjTable;
    ENDPROC
ENDMODULE
