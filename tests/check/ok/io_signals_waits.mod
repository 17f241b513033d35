MODULE io_signals_waits
    ! I/O handling of a clamping fixture with two clamps, a part
    ! sensor, a group output for the recipe number and an analog
    ! pressure setpoint. Signals are declared in the program and bound
    ! to the EIO configuration with AliasIO.

    VAR signaldo do_clamp1;
    VAR signaldo do_clamp2;
    VAR signaldo do_lamp;
    VAR signaldo do_horn;
    VAR signaldi di_clamp1_closed;
    VAR signaldi di_clamp2_closed;
    VAR signaldi di_part_ok;
    VAR signaldi di_door_closed;
    VAR signalgo go_recipe;
    VAR signalgi gi_fixture_id;
    VAR signalao ao_pressure;
    VAR signalai ai_pressure;

    VAR bool bTimeout:=FALSE;
    VAR num nFixtureId:=0;
    CONST num CLAMP_TIME:=3;
    CONST num conveyor_infeed_wait_for_part_ok:=20;

    PROC main()
        bind_io;
        set_recipe 5,4.5;
        close_clamps;
        wait_for_part;
        open_clamps;
    ENDPROC

    PROC bind_io()
        AliasIO "DO_Clamp1",do_clamp1;
        AliasIO "DO_Clamp2",do_clamp2;
        AliasIO "DO_Lamp",do_lamp;
        AliasIO "DO_Horn",do_horn;
        AliasIO "DI_Clamp1Closed",di_clamp1_closed;
        AliasIO "DI_Clamp2Closed",di_clamp2_closed;
        AliasIO "DI_PartOk",di_part_ok;
        AliasIO "DI_DoorClosed",di_door_closed;
        AliasIO "GO_Recipe",go_recipe;
        AliasIO "GI_FixtureId",gi_fixture_id;
        AliasIO "AO_PressureSet",ao_pressure;
        AliasIO "AI_Pressure",ai_pressure;
    ERROR
        IF ERRNO=ERR_ALIASIO_DEF OR ERRNO=ERR_NO_ALIASIO_DEF THEN
            TPWrite "I/O alias problem, check EIO.cfg";
        ENDIF
        RAISE;
    ENDPROC

    PROC set_recipe(num recipe,num bar)
        nFixtureId:=GInput(gi_fixture_id);
        SetGO go_recipe,recipe;
        SetAO ao_pressure,bar;
        ! Wait until the real pressure is within 0.2 bar of the setpoint
        WaitUntil Abs(AInput(ai_pressure)-bar)<0.2\MaxTime:=5\TimeFlag:=bTimeout\PollRate:=0.05;
        IF bTimeout TPWrite "Pressure not reached, actual "\Num:=AInput(ai_pressure);
    ENDPROC

    PROC close_clamps()
        WaitDI di_door_closed,1;
        ! Clamp 1 immediately, clamp 2 delayed by 0.3 s
        Set do_clamp1;
        SetDO\SDelay:=0.3,do_clamp2,1;
        WaitUntil di_clamp1_closed=1 AND di_clamp2_closed=1\MaxTime:=CLAMP_TIME;
        SetDO\Sync,do_lamp,1;
    ERROR
        IF ERRNO=ERR_WAIT_MAXTIME THEN
            alarm_pulse;
            Reset do_clamp1;
            Reset do_clamp2;
            WaitTime 1;
            Set do_clamp1;
            SetDO do_clamp2,high;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC wait_for_part()
        WaitDI di_part_ok,1\MaxTime:=conveyor_infeed_wait_for_part_ok\TimeFlag:=bTimeout;
        IF bTimeout THEN
            TPWrite "No part OK signal within "\Num:=conveyor_infeed_wait_for_part_ok;
        ENDIF
        WaitUntil\InPos,TestDI(di_part_ok);
    ENDPROC

    PROC open_clamps()
        Reset do_clamp2;
        Reset do_clamp1;
        WaitDI di_clamp1_closed,0;
        WaitDI di_clamp2_closed,low;
        SetDO do_lamp,0;
        IF DOutput(do_clamp1)=0 AND DOutput(do_clamp2)=0 TPWrite "Fixture open";
    ENDPROC

    PROC alarm_pulse()
        PulseDO do_horn;
        PulseDO\High\PLength:=1.5,do_lamp;
        WaitTime 0.5;
        PulseDO\PLength:=0.25,do_horn;
    ENDPROC

ENDMODULE
