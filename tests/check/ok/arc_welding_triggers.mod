MODULE arc_welding_triggers
    !=================================================================
    ! MIG welding of a bracket on a two-station jig, without the Arc
    ! option: torch, gas and wire feed are switched along the path
    ! with TriggIO / TriggEquip and supervised with TriggInt.
    !=================================================================

    PERS tooldata tTorch:=[TRUE,[[118.5,0,392.2],[0.906308,0,0.422618,0]],[3.2,[-40,0,180],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjJig:=[FALSE,TRUE,"",[[1105,-220,640.5],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    ! Welding speeds (mm/s) as speeddata
    CONST speeddata vWeldRoot:=[8,200,5000,1000];
    CONST speeddata vWeldCap:=[12.5,200,5000,1000];
    CONST zonedata zWeld:=[FALSE,0.5,0.8,0.8,0.08,0.8,0.08];

    CONST robtarget pSeam1Start:=[[0,0,0],[0.270598,0.653281,-0.270598,0.653281],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pSeam1Mid:=[[60,0,0],[0.270598,0.653281,-0.270598,0.653281],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pSeam1End:=[[145.2,0,0],[0.270598,0.653281,-0.270598,0.653281],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pArcCir:=[[175,25,0],[0.270598,0.653281,-0.270598,0.653281],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pArcEnd:=[[175,60,0],[0.270598,0.653281,-0.270598,0.653281],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pCleaner:=[[-420,915,380],[0,0,1,0],[1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    ! Process signals
    VAR signaldo do_gas;
    VAR signaldo do_arc_on;
    VAR signaldo do_wire_inch;
    VAR signalao ao_wire_feed;
    VAR signalao ao_voltage;
    VAR signaldi di_arc_established;

    ! Trigger data
    VAR triggdata trGasOn;
    VAR triggdata trArcOn;
    VAR triggdata trArcOff;
    VAR triggdata trGasOff;
    VAR triggdata trWireCap;
    VAR triggdata trArcCheck;
    VAR triggdata trWeldTriggs{2};

    VAR intnum irArcCheck;
    PERS bool bDryRun:=FALSE;
    PERS num nArcFaults:=0;

    PROC main()
        init_process;
        MoveJ Offs(pSeam1Start,0,-30,80),v1000,z20,tTorch\WObj:=wobjJig;
        weld_seam_1;
        weld_corner_arc;
        clean_torch;
    ENDPROC

    PROC init_process()
        AliasIO "doGasValve",do_gas;
        AliasIO "doArcOn",do_arc_on;
        AliasIO "doWireInch",do_wire_inch;
        AliasIO "aoWireFeed",ao_wire_feed;
        AliasIO "aoWeldVoltage",ao_voltage;
        AliasIO "diArcEst",di_arc_established;
        IDelete irArcCheck;
        CONNECT irArcCheck WITH trap_arc_check;
        ! Pre-flow gas 0.3 s before the start point is reached
        TriggEquip trGasOn,0,0.3\DOp:=do_gas,1;
        ! Arc on exactly at the start point, set wire feed analog output
        TriggIO trArcOn,0\DOp:=do_arc_on,1\Inhib:=bDryRun;
        TriggIO trWireCap,0\Start\AOp:=ao_wire_feed,7.5;
        ! Arc off 2 mm before the end point, gas off 0.1 s before the end point
        TriggIO trArcOff,2\DOp:=do_arc_on,0;
        TriggIO trGasOff,0.1\Time\DOp:=do_gas,0;
        ! Check the arc 15 mm after the start of the seam
        TriggInt trArcCheck,15\Start,irArcCheck;
        ! Trigger array for the cap pass: arc on plus a higher wire feed
        TriggIO trWeldTriggs{1},0\DOp:=do_arc_on,1\Inhib:=bDryRun;
        TriggIO trWeldTriggs{2},5\Start\AOp:=ao_wire_feed,9.2;
    ENDPROC

    PROC weld_seam_1()
        SetAO ao_voltage,21.5;
        MoveL Offs(pSeam1Start,0,0,10),v200,z1,tTorch\WObj:=wobjJig;
        TriggL pSeam1Start,v100,trGasOn,fine,tTorch\WObj:=wobjJig;
        TriggL pSeam1Mid,vWeldRoot,trArcOn\T2:=trWireCap\T3:=trArcCheck,zWeld,tTorch\WObj:=wobjJig;
        TriggL pSeam1End,vWeldRoot,trArcOff\T2:=trGasOff,fine,tTorch\WObj:=wobjJig;
        MoveL Offs(pSeam1End,0,0,40),v300,z10,tTorch\WObj:=wobjJig;
    ENDPROC

    PROC weld_corner_arc()
        SetAO ao_voltage,23;
        MoveL Offs(pSeam1End,0,0,10),v200,z1,tTorch\WObj:=wobjJig;
        TriggL pSeam1End,v100,trGasOn,fine,tTorch\WObj:=wobjJig;
        ! Array form of the trigger argument
        TriggL Offs(pSeam1End,15,5,0),vWeldCap,trWeldTriggs,zWeld,tTorch\WObj:=wobjJig;
        TriggC pArcCir,pArcEnd,vWeldCap,trArcOff\T2:=trGasOff,fine,tTorch\WObj:=wobjJig;
        MoveL Offs(pArcEnd,0,0,60),v500,z20,tTorch\WObj:=wobjJig;
    ENDPROC

    PROC clean_torch()
        MoveJ Offs(pCleaner,0,0,150),v1500,z50,tTorch;
        MoveL pCleaner,v200,fine,tTorch;
        PulseDO\PLength:=1.5,do_wire_inch;
        WaitTime 2;
        MoveL Offs(pCleaner,0,0,150),v500,z50,tTorch;
    ENDPROC

    TRAP trap_arc_check
        IF di_arc_established=0 THEN
            Incr nArcFaults;
            Reset do_arc_on;
            ErrWrite\W,"Arc not established","Seam 1 welded without arc"\RL2:="Check wire stick-out and gas";
        ENDIF
    ENDTRAP

ENDMODULE
