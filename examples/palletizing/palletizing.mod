MODULE palletizing
    !-----------------------------------------------------------------
    ! Palletizing: twelve 50 mm boxes from a fixed pick place onto a
    ! small pallet, two layers of a 2 x 3 pattern. The places are an
    ! array of robtargets in the pallet's frame; every approach and
    ! retreat is RelTool along the gripper's axis; a layer is an offset.
    !-----------------------------------------------------------------

    ! A suction gripper, 100 mm from the flange, pointing down.
    PERS tooldata tGripper := [TRUE,[[0,0,100],[1,0,0,0]],[0.5,[0,0,40],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjPallet := [FALSE,TRUE,"",[[200,100,100],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadBox := [0.3,[0,0,25],[1,0,0,0],0,0,0];

    CONST jointtarget jHome := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! Where boxes arrive (world), and home as a TCP position.
    CONST robtarget pPick := [[250,-250,150],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pHome := [[302,0,458],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! The first layer's places: the gripper on a box's top face (pallet frame).
    CONST robtarget pPlace{6} := [
        [[0,0,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
        [[80,0,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
        [[0,80,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
        [[80,80,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
        [[0,160,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],
        [[80,160,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];

    CONST num nLayers := 2;
    CONST num nBoxHeight := 50;
    CONST num nClearance := 100;
    CONST speeddata vTransfer := [400,500,5000,1000];

    VAR num nBoxes := 0;

    PROC main()
        Reset doGrip;
        MoveAbsJ jHome, v1000, fine, tGripper;
        MoveL pPick, vTransfer, fine, tGripper;
        FOR layer FROM 1 TO nLayers DO
            FOR i FROM 1 TO Dim(pPlace, 1) DO
                Pick;
                Place Offs(pPlace{i}, 0, 0, (layer - 1) * nBoxHeight);
            ENDFOR
            TPWrite "Layer " \Num:=layer;
        ENDFOR
        MoveL RelTool(pPick, 0, 0, -nClearance), vTransfer, z20, tGripper;
        MoveL pHome, vTransfer, fine, tGripper;
        TPWrite "Boxes on the pallet: " \Num:=nBoxes;
    ENDPROC

    ! The gripper is at the pick place: grip the box.
    PROC Pick()
        Set doGrip;
        WaitTime 0.2;
        GripLoad loadBox;
    ENDPROC

    ! Up, across and down onto the place, release, and back to the pick place.
    PROC Place(robtarget target)
        MoveL RelTool(pPick, 0, 0, -nClearance), vTransfer, z20, tGripper;
        MoveL RelTool(target, 0, 0, -nClearance), vTransfer, z20, tGripper \WObj:=wobjPallet;
        MoveL target, vTransfer, fine, tGripper \WObj:=wobjPallet;
        Reset doGrip;
        WaitTime 0.2;
        GripLoad load0;
        nBoxes := nBoxes + 1;
        IF nBoxes < nLayers * Dim(pPlace, 1) THEN
            MoveL RelTool(target, 0, 0, -nClearance), vTransfer, z20, tGripper \WObj:=wobjPallet;
            MoveL RelTool(pPick, 0, 0, -nClearance), vTransfer, z20, tGripper;
            MoveL pPick, vTransfer, fine, tGripper;
        ELSE
            MoveL RelTool(target, 0, 0, -nClearance), vTransfer, fine, tGripper \WObj:=wobjPallet;
        ENDIF
    ENDPROC
ENDMODULE
