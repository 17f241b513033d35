MODULE pick_and_place
    !***********************************************************
    ! Cell 12 - pick and place of machined flanges
    ! Picks a flange from the infeed nest and places it in the
    ! outfeed fixture. Gripper with part-present sensor.
    !
    ! Rev  Date        Sign  Note
    ! 1.0  2019-03-04  JKL   First version
    ! 1.1  2019-05-21  JKL   Retry on gripper timeout
    !***********************************************************

    ! Tool and work object data
    PERS tooldata tGripper:=[TRUE,[[0,0,185.5],[1,0,0,0]],[2.4,[0,0,80],[1,0,0,0],0.012,0.012,0.008]];
    PERS wobjdata wobjInfeed:=[FALSE,TRUE,"",[[820,-410,215],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS wobjdata wobjOutfeed:=[FALSE,TRUE,"",[[810,395,230],[0.707107,0,0,0.707107]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadFlange:=[3.15,[0,0,42],[1,0,0,0],0.011,0.011,0.018];

    ! Taught positions (relative to the work objects above)
    CONST robtarget pHome:=[[600,0,850],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pPick:=[[55,60,12],[0,0.707107,0.707107,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pPlace:=[[120,80,25.5],[0,0,1,0],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    ! Cell signals, bound to the configured names at start
    VAR signaldo do_grip_close;
    VAR signaldo do_grip_open;
    VAR signaldi di_grip_closed;
    VAR signaldi di_part_present;
    VAR signaldi di_outfeed_free;

    CONST num pick_station_approach_offset_mm1:=120;
    CONST num GRIP_TIMEOUT:=2.5;
    VAR num nPartsDone:=0;
    VAR bool bGripTimeout:=FALSE;
    PERS num nTotalParts:=0;

    PROC main()
        init_cell;
        MoveJ pHome,v1000,z50,tGripper;
        WHILE TRUE DO
            pick_part;
            place_part;
            Incr nPartsDone;
            nTotalParts:=nTotalParts+1;
            TPWrite "Parts this shift: "\Num:=nPartsDone;
        ENDWHILE
    ENDPROC

    PROC init_cell()
        AliasIO "DO10_1_GripClose",do_grip_close;
        AliasIO "DO10_2_GripOpen",do_grip_open;
        AliasIO "DI10_1_GripClosed",di_grip_closed;
        AliasIO "DI10_2_PartPresent",di_part_present;
        AliasIO "DI10_3_OutfeedFree",di_outfeed_free;
        open_gripper;
        GripLoad load0;
        nPartsDone:=0;
    ENDPROC

    PROC pick_part()
        ! Wait for a part in the nest before approaching
        WaitDI di_part_present,1;
        MoveJ Offs(pPick,0,0,pick_station_approach_offset_mm1),v1000,z50,tGripper\WObj:=wobjInfeed;
        MoveL Offs(pPick,0,0,20),v400,z5,tGripper\WObj:=wobjInfeed;
        MoveL pPick,v100,fine,tGripper\WObj:=wobjInfeed;
        close_gripper;
        GripLoad loadFlange;
        ! Lift straight up along the tool Z axis and tilt away from the nest wall
        MoveL RelTool(pPick,0,0,-50),v200,z10,tGripper\WObj:=wobjInfeed;
        MoveL RelTool(pPick,0,0,-150\Rx:=5),v800,z50,tGripper\WObj:=wobjInfeed;
    ENDPROC

    PROC place_part()
        WaitDI di_outfeed_free,1;
        MoveJ Offs(pPlace,0,0,pick_station_approach_offset_mm1),v1000,z50,tGripper\WObj:=wobjOutfeed;
        MoveL Offs(pPlace,0,0,10),v300,z1,tGripper\WObj:=wobjOutfeed;
        MoveL pPlace,v50,fine,tGripper\WObj:=wobjOutfeed;
        open_gripper;
        GripLoad load0;
        MoveL Offs(pPlace,0,0,pick_station_approach_offset_mm1),v500,z50,tGripper\WObj:=wobjOutfeed;
    ENDPROC

    PROC close_gripper()
        Reset do_grip_open;
        Set do_grip_close;
        WaitDI di_grip_closed,1\MaxTime:=GRIP_TIMEOUT;
    ERROR
        IF ERRNO=ERR_WAIT_MAXTIME THEN
            TPWrite "Gripper did not close - retrying";
            Reset do_grip_close;
            WaitTime 0.5;
            Set do_grip_close;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC open_gripper()
        Reset do_grip_close;
        Set do_grip_open;
        WaitDI di_grip_closed,0\MaxTime:=GRIP_TIMEOUT\TimeFlag:=bGripTimeout;
        IF bGripTimeout THEN
            TPWrite "Warning: gripper open feedback missing";
        ENDIF
    ENDPROC

ENDMODULE
