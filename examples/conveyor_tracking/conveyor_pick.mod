MODULE conveyor_pick
    !-----------------------------------------------------------------
    ! Pick three boxes off the conveyor CNV1 while they move, and stack
    ! them on a table. The conveyor's work object rides the conveyor
    ! (ufprog FALSE, ufmec "CNV1"): after WaitWObj the robot follows the
    ! box in every move made in it. A move in the table's work object
    ! ends the tracking; DropWObj then releases the box's place in the
    ! conveyor's queue.
    !-----------------------------------------------------------------

    PERS wobjdata wobjCnv := [FALSE,FALSE,"CNV1",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS wobjdata wobjTable := [FALSE,TRUE,"",[[300,-200,250],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    CONST robtarget pHome := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pAbove := [[0,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pGrip := [[0,0,20],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pStack := [[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    CONST num nBoxes := 3;
    CONST num nBoxHeight := 30;

    PROC main()
        ConfL \Off;
        Reset doGrip;
        MoveJ pHome, v1000, fine, tool0;
        FOR i FROM 0 TO nBoxes - 1 DO
            PickBox;
            StackBox i * nBoxHeight;
        ENDFOR
        MoveJ pHome, v1000, fine, tool0;
        TPWrite "Boxes stacked: " \Num:=nBoxes;
    ENDPROC

    PROC PickBox()
        WaitWObj wobjCnv;
        MoveL pAbove, v500, fine, tool0 \WObj:=wobjCnv;
        MoveL pGrip, v200, fine, tool0 \WObj:=wobjCnv;
        Set doGrip;
        WaitTime 0.2;
        MoveL pAbove, v500, fine, tool0 \WObj:=wobjCnv;
    ENDPROC

    PROC StackBox(num height)
        MoveL Offs(pStack, 0, 0, height + 130), v500, fine, tool0 \WObj:=wobjTable;
        DropWObj wobjCnv;
        MoveL Offs(pStack, 0, 0, height), v200, fine, tool0 \WObj:=wobjTable;
        Reset doGrip;
        WaitTime 0.2;
        MoveL Offs(pStack, 0, 0, height + 130), v500, fine, tool0 \WObj:=wobjTable;
    ENDPROC
ENDMODULE
