MODULE system_info_introspection
    ! Start-up checks: controller identity, operating and run mode,
    ! task name, and some data introspection (Type, IsPers, IsVar,
    ! ArgName) used by a generic parameter logger.

    PERS num nPersCounter:=0;
    VAR num nVarCounter:=0;
    PERS string sLastRobotType:="";
    VAR string sInfo;
    VAR errnum enSample:=0;

    PROC main()
        check_controller;
        describe_data nPersCounter;
        describe_data nVarCounter;
        TPWrite "Type of sInfo: "+Type(sInfo);
        TPWrite "Type of enSample: "+Type(enSample);
        TPWrite "Base type of enSample: "+Type(enSample\BaseName);
    ENDPROC

    PROC check_controller()
        sInfo:=GetSysInfo(\SerialNo);
        TPWrite "Serial number: "+sInfo;
        TPWrite "RobotWare: "+GetSysInfo(\SWVersion);
        sLastRobotType:=GetSysInfo(\RobotType);
        TPWrite "Robot type: "+sLastRobotType;
        TPWrite "Task: "+GetTaskName();
        IF RobOS() THEN
            TPWrite "Running on a real controller";
        ELSE
            TPWrite "Running on a virtual controller";
        ENDIF
        TEST OpMode()
        CASE OP_AUTO:
            TPWrite "Automatic mode";
        CASE OP_MAN_PROG:
            TPWrite "Manual reduced speed";
        CASE OP_MAN_TEST:
            TPWrite "Manual full speed";
        DEFAULT:
            TPWrite "Operating mode unknown";
        ENDTEST
        IF RunMode()=RUN_CONT_CYCLE THEN
            TPWrite "Continuous run";
        ELSEIF RunMode()=RUN_INSTR_FWD THEN
            TPWrite "Stepping forward";
        ENDIF
    ENDPROC

    ! Works for variables and persistents alike
    PROC describe_data(INOUT num value)
        IF IsPers(value) THEN
            TPWrite ArgName(value)+" is a persistent";
        ELSEIF IsVar(value) THEN
            TPWrite ArgName(value)+" is a variable";
        ENDIF
        value:=value+1;
    ENDPROC

ENDMODULE
