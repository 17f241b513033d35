MODULE WeldRoutines
    ! Generic seam welding, switching the power source with
    ! TriggIO events along the path.

    VAR signaldo do_arc;
    VAR signalao ao_volt;
    VAR triggdata trArcOn;
    VAR triggdata trArcOff;
    LOCAL VAR bool bIoBound:=FALSE;

    PROC weld_init()
        IF NOT bIoBound THEN
            AliasIO "doArcOn",do_arc;
            AliasIO "aoVoltage",ao_volt;
            bIoBound:=TRUE;
        ENDIF
        TriggIO trArcOn,0\DOp:=do_arc,1;
        TriggIO trArcOff,1\DOp:=do_arc,0;
    ENDPROC

    PROC weld_seam(robtarget start,seam_def seam)
        VAR speeddata vSeam;
        vSeam:=[seam.speed,200,5000,1000];
        SetAO ao_volt,seam.voltage;
        MoveJ Offs(start,0,0,50),v1000,z20,tTorch\WObj:=wobjFixture;
        MoveL start,v200,fine,tTorch\WObj:=wobjFixture;
        TriggL Offs(start,5,0,0),vSeam,trArcOn,z1,tTorch\WObj:=wobjFixture;
        TriggL Offs(start,seam.length,0,0),vSeam,trArcOff,fine,tTorch\WObj:=wobjFixture;
        MoveL Offs(start,seam.length,0,50),v500,z20,tTorch\WObj:=wobjFixture;
        nSeamsWelded:=nSeamsWelded+1;
        log_event "Seam "+seam.name+" welded";
    ERROR
        SetDO do_arc,0;
        log_event "Seam "+seam.name+" aborted";
        RAISE;
    ENDPROC

ENDMODULE
