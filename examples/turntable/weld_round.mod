MODULE weld_round
    !-----------------------------------------------------------------
    ! Weld half way round a part on the turntable STN1. The table's work
    ! object rides the table (ufprog FALSE, ufmec "STN1"): a move in it
    ! reaches its point on the part while the table turns to the
    ! target's eax_a, so the robot follows the part. A move in a fixed
    ! work object ends the following; MoveExtJ turns the table alone.
    !-----------------------------------------------------------------

    PERS wobjdata wobjTable := [FALSE,FALSE,"STN1",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    CONST robtarget pHome := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! The seam's start on the part's rim, 100 mm from the table's axis, 200 mm up.
    CONST robtarget pSeam := [[-100,0,200],[0,0,1,0],[0,0,0,0],[0,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jTableHome := [[9E9,9E9,9E9,9E9,9E9,9E9],[0,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        VAR robtarget pSeamEnd;
        ConfL \Off;
        Reset doArc;
        MoveJ pHome, v1000, fine, tool0;
        ! pHome is the seam's start: the robot is there already.
        MoveL pSeam, v100, fine, tool0 \WObj:=wobjTable;
        SetDO doArc, 1;
        ! The same point on the part, with the table turned half a turn.
        pSeamEnd := pSeam;
        pSeamEnd.extax.eax_a := 180;
        MoveL pSeamEnd, v100, fine, tool0 \WObj:=wobjTable;
        SetDO doArc, 0;
        MoveL pHome, v1000, fine, tool0;
        MoveExtJ jTableHome, v1000, fine;
        TPWrite "Seam welded";
    ENDPROC
ENDMODULE
