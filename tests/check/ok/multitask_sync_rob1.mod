MODULE multitask_sync_rob1
    !----------------------------------------------------------------
    ! Task T_ROB1 of a two-robot cell (MultiMove independent).
    ! Both robots load the same turntable; the common area above the
    ! table is protected with a semaphore, and the robots meet at
    ! sync points before and after each table index.
    !----------------------------------------------------------------

    ! Shared with T_ROB2 and the background task T_PLC (system global)
    PERS bool bTableAreaBusy:=FALSE;
    PERS num nTableParts:=0;
    PERS bool bStopRequest:=FALSE;
    PERS string sLastWriter:="";
    ! Each task has its own value of this persistent
    TASK PERS num nMyCycles:=0;
    TASK PERS tooldata tGun1:=[TRUE,[[0,0,305],[1,0,0,0]],[12,[0,0,140],[1,0,0,0],0.3,0.3,0.1]];
    ! Only visible in this module
    LOCAL PERS num nLocalFaults:=0;

    PERS tasks tlRobots{2}:=[["T_ROB1"],["T_ROB2"]];
    PERS tasks tlAllTasks{3}:=[["T_ROB1"],["T_ROB2"],["T_PLC"]];
    VAR syncident siCycleStart;
    VAR syncident siTableIndexed;
    VAR syncident siShutdown;

    CONST robtarget pTableLoad:=[[950,-150,620],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pWait:=[[600,-700,900],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        WHILE NOT bStopRequest DO
            WaitSyncTask siCycleStart,tlRobots\TimeOut:=120;
            load_table;
            WaitSyncTask\InPos,siTableIndexed,tlRobots;
            nMyCycles:=nMyCycles+1;
        ENDWHILE
        WaitSyncTask siShutdown,tlAllTasks;
    ERROR
        IF ERRNO=ERR_WAITSYNCTASK THEN
            TPWrite "T_ROB2 did not arrive at the sync point";
            Incr nLocalFaults;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC load_table()
        MoveJ pWait,v1500,z50,tGun1;
        ! Only one robot may be above the table at a time
        WaitTestAndSet bTableAreaBusy;
        sLastWriter:="T_ROB1";
        MoveL Offs(pTableLoad,0,0,200),v1000,z20,tGun1;
        MoveL pTableLoad,v200,fine,tGun1;
        nTableParts:=nTableParts+1;
        MoveL Offs(pTableLoad,0,0,200),v1000,z20,tGun1;
        MoveJ pWait,v1500,z50,tGun1;
        bTableAreaBusy:=FALSE;
    ENDPROC

    ! Non-blocking variant used by service routines
    FUNC bool try_enter_table_area()
        IF TestAndSet(bTableAreaBusy) THEN
            sLastWriter:="T_ROB1 service";
            RETURN TRUE;
        ENDIF
        RETURN FALSE;
    ENDFUNC

    PROC service_position()
        VAR num nTries:=0;
        WHILE NOT try_enter_table_area() DO
            nTries:=nTries+1;
            IF nTries>50 THEN
                TPWrite "Table area still busy, giving up";
                RETURN;
            ENDIF
            WaitTime 0.1;
        ENDWHILE
        MoveJ Offs(pTableLoad,0,0,400),v500,fine,tGun1;
        Stop;
        bTableAreaBusy:=FALSE;
    ENDPROC

ENDMODULE
