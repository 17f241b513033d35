MODULE palletizing_robtarget_arrays
    !-----------------------------------------------------------
    ! Palletizing of cartons on a EUR pallet (1200 x 800).
    ! The place grid is computed once into a 2-D robtarget array,
    ! every layer is stacked with a Z offset. Interleaved rows
    ! are filled from both ends using FOR loops with STEP.
    !-----------------------------------------------------------

    PERS tooldata tVacuum:=[TRUE,[[0,0,240],[1,0,0,0]],[6.8,[0,0,110],[1,0,0,0],0.09,0.09,0.05]];
    PERS wobjdata wobjPallet:=[FALSE,TRUE,"",[[1450,-600,95],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS wobjdata wobjConveyor:=[FALSE,TRUE,"",[[-200,1300,780],[0.707107,0,0,-0.707107]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadCarton:=[7.5,[0,0,95],[1,0,0,0],0.14,0.11,0.09];

    ! Corner of the first carton on the pallet (layer 1)
    CONST robtarget pPalletOrigin:=[[200,150,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pConveyorPick:=[[0,0,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    ! Two fixed reject positions, kept as a 2x2 constant array (row, side)
    CONST robtarget pReject{2,2}:=[[[[-300,-200,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[-300,200,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]],[[[-500,-200,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[-500,200,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]]]];

    CONST num ROWS:=3;
    CONST num COLS:=4;
    CONST num LAYERS:=5;
    CONST num CARTON_X:=400;
    CONST num CARTON_Y:=200;
    CONST num CARTON_H:=180;
    CONST num PalletLayerSeparatorSheetHeight1:=3.5;

    VAR robtarget pPlaceGrid{3,4};
    VAR num nLayer:=1;
    VAR num nPlaced:=0;
    VAR num nVacuumRetries:=0;
    VAR num nRejectSide:=1;

    VAR signaldo do_vacuum;
    VAR signaldi di_vacuum_ok;
    VAR signaldi di_carton_at_pick;

    PROC main()
        AliasIO "DO_Vacuum",do_vacuum;
        AliasIO "DI_VacuumOk",di_vacuum_ok;
        AliasIO "DI_CartonAtPick",di_carton_at_pick;
        build_grid;
        FOR layer FROM 1 TO LAYERS DO
            nLayer:=layer;
            IF layer MOD 2=1 THEN
                fill_layer_forward layer;
            ELSE
                fill_layer_reverse layer;
            ENDIF
        ENDFOR
        TPWrite "Pallet complete, cartons: "\Num:=nPlaced;
    ENDPROC

    ! Fill the place grid from the pallet origin
    PROC build_grid()
        FOR r FROM 1 TO ROWS DO
            FOR c FROM 1 TO COLS DO
                pPlaceGrid{r,c}:=Offs(pPalletOrigin,(c-1)*CARTON_Y,(r-1)*CARTON_X,0);
            ENDFOR
        ENDFOR
    ENDPROC

    PROC fill_layer_forward(num layer)
        VAR num z;
        z:=(layer-1)*(CARTON_H+PalletLayerSeparatorSheetHeight1);
        ! Odd rows left to right, even rows right to left
        FOR r FROM 1 TO ROWS STEP 2 DO
            FOR c FROM 1 TO COLS DO
                place_at pPlaceGrid{r,c},z;
            ENDFOR
        ENDFOR
        FOR r FROM 2 TO ROWS STEP 2 DO
            FOR c FROM COLS TO 1 STEP -1 DO
                place_at pPlaceGrid{r,c},z;
            ENDFOR
        ENDFOR
    ENDPROC

    PROC fill_layer_reverse(num layer)
        VAR num z;
        z:=(layer-1)*(CARTON_H+PalletLayerSeparatorSheetHeight1);
        FOR r FROM ROWS TO 1 STEP -1 DO
            FOR c FROM COLS TO 1 STEP -2 DO
                place_at pPlaceGrid{r,c},z;
            ENDFOR
            FOR c FROM COLS-1 TO 1 STEP -2 DO
                place_at pPlaceGrid{r,c},z;
            ENDFOR
        ENDFOR
    ENDPROC

    PROC place_at(robtarget target,num z_offset)
        pick_carton;
        MoveJ Offs(target,0,0,z_offset+250),v2000,z100,tVacuum\WObj:=wobjPallet;
        MoveL Offs(target,0,0,z_offset+30),v600,z10,tVacuum\WObj:=wobjPallet;
        MoveL Offs(target,0,0,z_offset),v100,fine,tVacuum\WObj:=wobjPallet;
        Reset do_vacuum;
        GripLoad load0;
        WaitTime 0.2;
        MoveL Offs(target,0,0,z_offset+250),v1500,z100,tVacuum\WObj:=wobjPallet;
        Incr nPlaced;
    ENDPROC

    PROC pick_carton()
        nVacuumRetries:=0;
        WaitDI di_carton_at_pick,1;
        MoveJ Offs(pConveyorPick,0,0,200),v2000,z50,tVacuum\WObj:=wobjConveyor;
        MoveL pConveyorPick,v300,fine,tVacuum\WObj:=wobjConveyor;
        Set do_vacuum;
        WaitDI di_vacuum_ok,1\MaxTime:=1.5;
        GripLoad loadCarton;
        MoveL Offs(pConveyorPick,0,0,200),v1000,z50,tVacuum\WObj:=wobjConveyor;
    ERROR
        IF ERRNO=ERR_WAIT_MAXTIME THEN
            nVacuumRetries:=nVacuumRetries+1;
            IF nVacuumRetries<3 THEN
                ! Re-seat the suction cup and wait again
                Reset do_vacuum;
                WaitTime 0.3;
                Set do_vacuum;
                RETRY;
            ENDIF
            ! Carton cannot be held: lift and drop it at a reject place
            Reset do_vacuum;
            MoveL Offs(pConveyorPick,0,0,200),v500,z50,tVacuum\WObj:=wobjConveyor;
            MoveJ pReject{1,nRejectSide},v1000,fine,tVacuum\WObj:=wobjConveyor;
            MoveJ pReject{2,nRejectSide},v1000,fine,tVacuum\WObj:=wobjConveyor;
            nRejectSide:=3-nRejectSide;
            nVacuumRetries:=0;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
