MODULE cycle_time_clocks
    ! Cycle time measurement with clock data.
    ! One clock for the whole cycle, one for the robot waiting time,
    ! statistics kept in persistents so they survive a restart.

    VAR clock clkCycle;
    VAR clock clkWait;
    VAR num nCycleTime:=0;
    VAR num nWaitTime:=0;
    PERS num nBestCycle:=9999;
    PERS num nWorstCycle:=0;
    PERS num nCycleSum:=0;
    PERS num nCycleCount:=0;
    PERS string sShiftStart:="";

    VAR signaldi di_machine_done;
    PERS tooldata tLoader:=[TRUE,[[0,0,175],[1,0,0,0]],[6,[0,0,80],[1,0,0,0],0.05,0.05,0.03]];
    CONST robtarget pMachine:=[[1100,0,900],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pBuffer:=[[300,900,700],[0,0,1,0],[1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        AliasIO "DI_MachineDone",di_machine_done;
        IF sShiftStart="" sShiftStart:=CDate()+" "+CTime();
        ClkReset clkWait;
        FOR cycle FROM 1 TO 10 DO
            ClkReset clkCycle;
            ClkStart clkCycle;
            tend_machine;
            ClkStop clkCycle;
            nCycleTime:=ClkRead(clkCycle);
            update_statistics nCycleTime;
        ENDFOR
        report;
    ENDPROC

    PROC tend_machine()
        MoveJ pBuffer,v2000,z50,tLoader;
        MoveJ Offs(pMachine,-200,0,0),v2000,z20,tLoader;
        ! Measure only the time spent waiting for the machine
        ClkStart clkWait;
        WaitDI di_machine_done,1;
        ClkStop clkWait;
        MoveL pMachine,v500,fine,tLoader;
        WaitTime\InPos,0.2;
        MoveL Offs(pMachine,-200,0,0),v1000,z20,tLoader;
    ENDPROC

    PROC update_statistics(num t)
        IF t<nBestCycle nBestCycle:=t;
        IF t>nWorstCycle nWorstCycle:=t;
        nCycleSum:=nCycleSum+t;
        nCycleCount:=nCycleCount+1;
    ENDPROC

    PROC report()
        VAR num nHighRes;
        nWaitTime:=ClkRead(clkWait);
        nHighRes:=ClkRead(clkCycle\HighRes);
        TPWrite "Shift started "+sShiftStart;
        TPWrite "Best cycle  [s]: "\Num:=nBestCycle;
        TPWrite "Worst cycle [s]: "\Num:=nWorstCycle;
        IF nCycleCount>0 TPWrite "Mean cycle  [s]: "\Num:=Round(nCycleSum/nCycleCount\Dec:=2);
        TPWrite "Waiting     [s]: "\Num:=nWaitTime;
        TPWrite "Last (high res): "\Num:=nHighRes;
        TPWrite "Weekday: "\Num:=GetTime(\WDay);
        TPWrite "Now: "+CTime();
    ERROR
        IF ERRNO=ERR_OVERFLOW THEN
            ! Clock ran for more than 49 days
            ClkReset clkWait;
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
