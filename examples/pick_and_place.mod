MODULE pick_and_place
    !-----------------------------------------------------------------
    ! Pick parts from an infeed conveyor and place them in a row of
    ! four nests on an outfeed pallet. Vacuum gripper on DO_Vacuum,
    ! part sensor on DI_PartReady.
    !-----------------------------------------------------------------

    PERS tooldata tVacuum := [TRUE,[[0,0,142.5],[1,0,0,0]],[1.2,[0,0,60],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjConveyor := [FALSE,TRUE,"",[[950,-400,310],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS wobjdata wobjPallet := [FALSE,TRUE,"",[[700,450,120],[0.707107,0,0,0.707107]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadPart := [0.8,[0,0,25],[1,0,0,0],0,0,0];

    CONST robtarget pHome := [[600,0,900],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pPick := [[120,35,15],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pPlace := [[50,50,20],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    CONST num nNests := 4;
    CONST num nPitch := 110;
    CONST num nApproach := 100;

    VAR signaldo doVacuum;
    VAR signaldi diPartReady;
    VAR num nPlaced := 0;

    PROC main()
        AliasIO "DO_Vacuum", doVacuum;
        AliasIO "DI_PartReady", diPartReady;
        Reset doVacuum;
        MoveJ pHome, v1000, z50, tVacuum;
        FOR i FROM 0 TO nNests - 1 DO
            PickPart;
            PlacePart i * nPitch;
        ENDFOR
        MoveJ pHome, v1000, fine, tVacuum;
        TPWrite "Parts placed: " \Num:=nPlaced;
    ENDPROC

    PROC PickPart()
        WaitDI diPartReady, 1;
        MoveJ Offs(pPick, 0, 0, nApproach), v1000, z20, tVacuum \WObj:=wobjConveyor;
        MoveL pPick, v200, fine, tVacuum \WObj:=wobjConveyor;
        Set doVacuum;
        WaitTime 0.3;
        GripLoad loadPart;
        MoveL Offs(pPick, 0, 0, nApproach), v500, z20, tVacuum \WObj:=wobjConveyor;
    ENDPROC

    PROC PlacePart(num xOffset)
        MoveJ Offs(pPlace, xOffset, 0, nApproach), v1000, z20, tVacuum \WObj:=wobjPallet;
        MoveL Offs(pPlace, xOffset, 0, 0), v200, fine, tVacuum \WObj:=wobjPallet;
        Reset doVacuum;
        WaitTime 0.2;
        GripLoad load0;
        MoveL Offs(pPlace, xOffset, 0, nApproach), v500, z20, tVacuum \WObj:=wobjPallet;
        nPlaced := nPlaced + 1;
    ENDPROC
ENDMODULE
