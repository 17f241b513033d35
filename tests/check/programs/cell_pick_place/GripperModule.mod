MODULE GripperModule
    ! Gripper handling shared by all routines of the program.
    ! Signals are bound once with grip_init.

    VAR signaldo do_grip;
    VAR signaldi di_gripped;
    VAR signaldi di_released;
    LOCAL VAR bool bInitDone:=FALSE;
    LOCAL CONST num GRIP_TIME:=1.5;

    PROC grip_init()
        IF bInitDone RETURN;
        AliasIO "DO_Grip",do_grip;
        AliasIO "DI_Gripped",di_gripped;
        AliasIO "DI_Released",di_released;
        bInitDone:=TRUE;
    ENDPROC

    PROC grip_close()
        SetDO do_grip,1;
        WaitDI di_gripped,1\MaxTime:=GRIP_TIME;
        GripLoad loadPart;
    ERROR
        IF ERRNO=ERR_WAIT_MAXTIME THEN
            nGripFaults:=nGripFaults+1;
            SetDO do_grip,0;
            WaitTime 0.3;
            SetDO do_grip,1;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC grip_open()
        SetDO do_grip,0;
        WaitDI di_released,1\MaxTime:=GRIP_TIME;
        GripLoad load0;
    ENDPROC

    FUNC bool grip_has_part()
        RETURN di_gripped=1;
    ENDFUNC

ENDMODULE
