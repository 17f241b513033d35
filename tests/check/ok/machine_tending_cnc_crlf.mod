MODULE machine_tending_cnc_crlf
    !---------------------------------------------------------------
    ! CNC machine tending with a double gripper (A = raw, B = finished).
    ! Handshake with the CNC over digital I/O:
    !   robot -> CNC : do_req_door_open, do_robot_clear, do_cycle_start
    !   CNC -> robot : di_door_open, di_cycle_done, di_chuck_open
    ! File edited on a PC, saved with CRLF line ends.
    !---------------------------------------------------------------

    PERS tooldata tGripA:=[TRUE,[[0,70,190],[1,0,0,0]],[5.9,[0,10,85],[1,0,0,0],0.05,0.05,0.03]];
    PERS tooldata tGripB:=[TRUE,[[0,-70,190],[1,0,0,0]],[5.9,[0,-10,85],[1,0,0,0],0.05,0.05,0.03]];
    PERS wobjdata wobjCnc:=[FALSE,TRUE,"",[[1820,150,1105],[0.707107,0,0,0.707107]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadRaw:=[2.7,[0,0,40],[1,0,0,0],0.004,0.004,0.005];
    PERS loaddata loadBoth:=[5.2,[0,0,40],[1,0,0,0],0.008,0.008,0.01];

    CONST robtarget pChuck:=[[0,0,0],[0.5,0.5,-0.5,0.5],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pOutsideDoor:=[[-600,0,250],[0.5,0.5,-0.5,0.5],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jParking:=[[-45,-15,25,0,70,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR signaldo do_req_door_open;
    VAR signaldo do_robot_clear;
    VAR signaldo do_cycle_start;
    VAR signaldo do_grip_a;
    VAR signaldo do_grip_b;
    VAR signaldo do_chuck_clamp;
    VAR signaldi di_door_open;
    VAR signaldi di_cycle_done;
    VAR signaldi di_chuck_open;

    VAR bool bFirstCycle:=TRUE;
    VAR bool bTimeout:=FALSE;
    PERS num nMachined:=0;

    PROC main()
        init_io;
        MoveAbsJ jParking,v1000,z50,tGripA;
        WHILE TRUE DO
            IF NOT bFirstCycle THEN
                WaitDI di_cycle_done,1;
            ENDIF
            open_door;
            exchange_parts;
            close_door_and_start;
            bFirstCycle:=FALSE;
        ENDWHILE
    ENDPROC

    PROC init_io()
        AliasIO "doCncReqDoor",do_req_door_open;
        AliasIO "doCncRobotClear",do_robot_clear;
        AliasIO "doCncCycleStart",do_cycle_start;
        AliasIO "doGripA",do_grip_a;
        AliasIO "doGripB",do_grip_b;
        AliasIO "doCncChuckClamp",do_chuck_clamp;
        AliasIO "diCncDoorOpen",di_door_open;
        AliasIO "diCncCycleDone",di_cycle_done;
        AliasIO "diCncChuckOpen",di_chuck_open;
        Set do_robot_clear;
    ENDPROC

    PROC open_door()
        Set do_req_door_open;
        WaitDI di_door_open,1\MaxTime:=20\TimeFlag:=bTimeout;
        IF bTimeout THEN
            ErrWrite\W,"CNC door","Door did not open within 20 s";
            WaitDI di_door_open,1;
        ENDIF
        Reset do_req_door_open;
    ENDPROC

    PROC exchange_parts()
        Reset do_robot_clear;
        MoveJ pOutsideDoor,v1500,z50,tGripB\WObj:=wobjCnc;
        IF NOT bFirstCycle THEN
            ! Take the finished part with gripper B
            MoveL Offs(pChuck,-100,0,0),v800,z10,tGripB\WObj:=wobjCnc;
            MoveL pChuck,v100,fine,tGripB\WObj:=wobjCnc;
            Set do_grip_b;
            WaitTime 0.4;
            Reset do_chuck_clamp;
            WaitDI di_chuck_open,1;
            GripLoad loadBoth;
            MoveL Offs(pChuck,-100,0,0),v300,z10,tGripB\WObj:=wobjCnc;
            nMachined:=nMachined+1;
        ENDIF
        ! Insert the raw part with gripper A
        MoveL Offs(pChuck,-100,0,0),v800,z10,tGripA\WObj:=wobjCnc;
        MoveL pChuck,v100,fine,tGripA\WObj:=wobjCnc;
        Set do_chuck_clamp;
        WaitTime 0.5;
        Reset do_grip_a;
        GripLoad loadRaw;
        MoveL Offs(pChuck,-100,0,0),v300,z10,tGripA\WObj:=wobjCnc;
        MoveL pOutsideDoor,v1500,z50,tGripA\WObj:=wobjCnc;
        Set do_robot_clear;
    ENDPROC

    PROC close_door_and_start()
        WaitDI di_chuck_open,0;
        PulseDO\PLength:=0.5,do_cycle_start;
        MoveAbsJ jParking,v1000,z50,tGripA;
    ENDPROC

ENDMODULE
