MODULE sysinfo_values
    ! System information of the virtual controller: the documented constants of
    ! crates/rapid-vm/src/builtins/sysinfo.rs (ours, not ABB's; uncertain), RobOS FALSE
    ! (virtual controller), automatic operating mode, continuous running.
    PROC main()
        VAR num n := 0;
        VAR string name;
        VAR string version;
        TPWrite "serial " + GetSysInfo(\SerialNo);
        TPWrite "version " + GetSysInfo(\SWVersion);
        TPWrite "version name " + GetSysInfo(\SWVersionName);
        TPWrite "robot " + GetSysInfo(\RobotType);
        TPWrite "ctrl id " + GetSysInfo(\CtrlId);
        TPWrite "lan ip " + GetSysInfo(\LanIp);
        TPWrite "lang " + GetSysInfo(\CtrlLang);
        TPWrite "system " + GetSysInfo(\SystemName);
        TPWrite "is sys id " \Bool:=IsSysId(GetSysInfo(\SerialNo));
        TPWrite "is other id " \Bool:=IsSysId("44-12345");
        TPWrite "robos " \Bool:=RobOS();
        TPWrite "auto " \Bool:=OpMode() = OP_AUTO;
        TPWrite "manual " \Bool:=OpMode() = OP_MAN_PROG;
        TPWrite "continuous " \Bool:=RunMode() = RUN_CONT_CYCLE;
        TPWrite "continuous main " \Bool:=RunMode(\Main) = RUN_CONT_CYCLE;
        TPWrite "non-motion " \Bool:=NonMotionMode();
        TPWrite "memory " \Num:=ProgMemFree() DIV 1024;
        TPWrite "event none " \Bool:=EventType() = EVENT_NONE;
        ! ListNumber counts from 0 and is advanced by every call.
        WHILE GetNextOption(n, name) DO
            TPWrite "option " + name;
        ENDWHILE
        TPWrite "after options n=" \Num:=n;
        n := 0;
        WHILE GetNextProduct(n, name \Version:=version) DO
            TPWrite "product " + name + " " + version;
        ENDWHILE
        TPWrite "after products n=" \Num:=n;
    ENDPROC
ENDMODULE
