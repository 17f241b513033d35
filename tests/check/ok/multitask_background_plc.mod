MODULE multitask_background_plc(NOSTEPIN)
    !----------------------------------------------------------------
    ! Semistatic background task T_PLC (no motion). Mirrors cell
    ! persistents to PLC signals, counts parts and raises the stop
    ! request for the motion tasks at end of shift.
    !----------------------------------------------------------------

    PERS bool bTableAreaBusy:=FALSE;
    PERS num nTableParts:=0;
    PERS bool bStopRequest:=FALSE;
    PERS string sLastWriter:="";
    TASK PERS num nMyCycles:=0;

    PERS tasks tlAllTasks{3}:=[["T_ROB1"],["T_ROB2"],["T_PLC"]];
    VAR syncident siShutdown;

    VAR signalgo go_part_count;
    VAR signaldo do_table_busy;
    VAR signaldi di_end_of_shift;
    VAR signaldo do_heartbeat;
    VAR intnum irShiftEnd;
    VAR string sTaskName;

    PROC main()
        sTaskName:=GetTaskName();
        AliasIO "goPartCount",go_part_count;
        AliasIO "doTableBusy",do_table_busy;
        AliasIO "diEndOfShift",di_end_of_shift;
        AliasIO "doPlcHeartbeat",do_heartbeat;
        IDelete irShiftEnd;
        CONNECT irShiftEnd WITH trap_shift_end;
        ISignalDI\Single,di_end_of_shift,1,irShiftEnd;
        WHILE NOT bStopRequest DO
            mirror_signals;
            nMyCycles:=nMyCycles+1;
            WaitTime 0.2;
        ENDWHILE
        WaitSyncTask siShutdown,tlAllTasks\TimeOut:=300;
        IDelete irShiftEnd;
    ENDPROC

    PROC mirror_signals()
        IF nTableParts>65535 nTableParts:=0;
        SetGO go_part_count,nTableParts;
        IF bTableAreaBusy THEN
            SetDO do_table_busy,1;
        ELSE
            SetDO do_table_busy,0;
        ENDIF
        PulseDO\High\PLength:=0.1,do_heartbeat;
    ENDPROC

    TRAP trap_shift_end
        TPWrite sTaskName+": end of shift requested by "+sLastWriter;
        bStopRequest:=TRUE;
    ENDTRAP

ENDMODULE
