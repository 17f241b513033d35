MODULE undo_handlers_cleanup
    ! UNDO handlers make sure that files are closed, outputs are reset
    ! and interrupts are removed when the operator moves the program
    ! pointer out of a routine (PP to Main) in the middle of a cycle.

    VAR iodev ioReport;
    VAR bool bReportOpen:=FALSE;
    VAR intnum irPressure;
    VAR bool bPressureArmed:=FALSE;
    VAR num nOpenHandles:=0;

    VAR signaldo do_dispense;
    VAR signaldi di_pressure_low;

    PERS tooldata tNozzle:=[TRUE,[[2,0,155.5],[1,0,0,0]],[1.2,[0,0,60],[1,0,0,0],0,0,0]];
    CONST robtarget pBead{4}:=[[[400,-100,250],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[400,100,250],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[600,100,250],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[600,-100,250],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];

    PROC main()
        AliasIO "doDispense",do_dispense;
        AliasIO "diPressureLow",di_pressure_low;
        open_report;
        dispense_bead;
        close_report;
    UNDO
        TPWrite "Cycle aborted, cleaning up";
        IF bReportOpen THEN
            Close ioReport;
            bReportOpen:=FALSE;
        ENDIF
    ENDPROC

    PROC open_report()
        Open "HOME:"\File:="bead_report.txt",ioReport\Write;
        bReportOpen:=TRUE;
        nOpenHandles:=nOpenHandles+1;
        Write ioReport,"Bead report "+CDate();
    ENDPROC

    PROC close_report()
        Write ioReport,"End of report";
        Close ioReport;
        bReportOpen:=FALSE;
        nOpenHandles:=nOpenHandles-1;
    ENDPROC

    PROC dispense_bead()
        arm_pressure_watch;
        MoveL Offs(pBead{1},0,0,30),v500,z10,tNozzle;
        MoveL pBead{1},v100,fine,tNozzle;
        SetDO do_dispense,1;
        FOR i FROM 2 TO Dim(pBead,1) DO
            MoveL pBead{i},v80,z1,tNozzle;
            Write ioReport,"Corner "\Num:=i;
        ENDFOR
        MoveL pBead{1},v80,fine,tNozzle;
        SetDO do_dispense,0;
        MoveL Offs(pBead{1},0,0,30),v500,z10,tNozzle;
        disarm_pressure_watch;
    UNDO
        ! Never leave the dispenser running
        SetDO do_dispense,0;
        disarm_pressure_watch;
    ENDPROC

    PROC arm_pressure_watch()
        CONNECT irPressure WITH trap_pressure;
        ISignalDI di_pressure_low,1,irPressure;
        bPressureArmed:=TRUE;
    ENDPROC

    PROC disarm_pressure_watch()
        IF bPressureArmed THEN
            IDelete irPressure;
            bPressureArmed:=FALSE;
        ENDIF
    ENDPROC

    ! A function with an UNDO handler: the temporary file is removed
    ! if execution is aborted while it is being written
    FUNC num write_checksum_file(num value)
        VAR iodev ioTmp;
        Open "TEMP:"\File:="chk.tmp",ioTmp\Write;
        Write ioTmp,"checksum="\Num:=value;
        Close ioTmp;
        RETURN value MOD 97;
    ERROR
        RETURN -1;
    UNDO
        Close ioTmp;
        RemoveFile "TEMP:/chk.tmp";
    ENDFUNC

    TRAP trap_pressure
        SetDO do_dispense,0;
        TPWrite "Glue pressure low - bead interrupted";
        StopMove;
    ENDTRAP

ENDMODULE
