MODULE cell_state_machine
    ! Main sequence of a two-fixture welding cell written as a state
    ! machine. The PLC selects the fixture, the robot reports its state
    ! on a group output. States are numeric constants.

    CONST num ST_INIT:=0;
    CONST num ST_WAIT_FIXTURE:=10;
    CONST num ST_WELD_F1:=20;
    CONST num ST_WELD_F2:=30;
    CONST num ST_SERVICE:=40;
    CONST num ST_FAULT:=90;
    CONST num ST_STOPPED:=99;

    VAR num nState:=0;
    VAR num nPrevState:=-1;
    VAR num nFaultCode:=0;
    VAR num nCycles:=0;
    VAR bool bRunning:=TRUE;

    VAR signaldi di_f1_ready;
    VAR signaldi di_f2_ready;
    VAR signaldi di_service_req;
    VAR signaldi di_stop_req;
    VAR signalgo go_robot_state;

    PERS tooldata tWeld:=[TRUE,[[95,0,365],[0.965926,0,0.258819,0]],[3.5,[0,0,140],[1,0,0,0],0,0,0]];
    CONST robtarget pF1Seam:=[[1100,-500,600],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pF2Seam:=[[1100,500,600],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pService:=[[600,0,1200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jHome:=[[0,-20,20,0,70,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        nState:=ST_INIT;
        WHILE bRunning DO
            IF nState<>nPrevState THEN
                SetGO go_robot_state,nState;
                nPrevState:=nState;
            ENDIF
            TEST nState
            CASE ST_INIT:
                state_init;
            CASE ST_WAIT_FIXTURE:
                state_wait;
            CASE ST_WELD_F1,ST_WELD_F2:
                state_weld;
            CASE ST_SERVICE:
                state_service;
            CASE ST_FAULT:
                state_fault;
            CASE ST_STOPPED:
                bRunning:=FALSE;
            DEFAULT:
                nFaultCode:=1;
                nState:=ST_FAULT;
            ENDTEST
        ENDWHILE
        TPWrite "Cell stopped after cycles: "\Num:=nCycles;
    ENDPROC

    PROC state_init()
        AliasIO "DI_Fixture1Ready",di_f1_ready;
        AliasIO "DI_Fixture2Ready",di_f2_ready;
        AliasIO "DI_ServiceRequest",di_service_req;
        AliasIO "DI_StopRequest",di_stop_req;
        AliasIO "GO_RobotState",go_robot_state;
        MoveAbsJ jHome,v1000,fine,tWeld;
        nState:=ST_WAIT_FIXTURE;
    ENDPROC

    PROC state_wait()
        WaitUntil di_f1_ready=1 OR di_f2_ready=1 OR di_service_req=1 OR di_stop_req=1;
        IF di_stop_req=1 THEN
            nState:=ST_STOPPED;
        ELSEIF di_service_req=1 THEN
            nState:=ST_SERVICE;
        ELSEIF di_f1_ready=1 THEN
            nState:=ST_WELD_F1;
        ELSE
            nState:=ST_WELD_F2;
        ENDIF
    ENDPROC

    PROC state_weld()
        VAR robtarget pSeam;
        IF nState=ST_WELD_F1 THEN
            pSeam:=pF1Seam;
        ELSE
            pSeam:=pF2Seam;
        ENDIF
        MoveJ Offs(pSeam,0,0,100),v1500,z20,tWeld;
        MoveL pSeam,v200,fine,tWeld;
        MoveL Offs(pSeam,250,0,0),v20,fine,tWeld;
        MoveL Offs(pSeam,250,0,100),v500,z20,tWeld;
        MoveAbsJ jHome,v1500,z50,tWeld;
        nCycles:=nCycles+1;
        nState:=ST_WAIT_FIXTURE;
    ERROR
        nFaultCode:=ERRNO;
        nState:=ST_FAULT;
        RETURN;
    ENDPROC

    PROC state_service()
        MoveJ pService,v500,fine,tWeld;
        TPWrite "Service position - press START when done";
        Stop;
        MoveAbsJ jHome,v500,fine,tWeld;
        nState:=ST_WAIT_FIXTURE;
    ENDPROC

    PROC state_fault()
        ErrWrite "Cell fault","Fault code "+NumToStr(nFaultCode,0);
        Stop;
        nFaultCode:=0;
        nState:=ST_INIT;
    ENDPROC

ENDMODULE
