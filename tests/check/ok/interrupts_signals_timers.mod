MODULE interrupts_signals_timers
    ! Interrupt handling for a deburring cell:
    !  - light curtain (falling edge) stops the spindle immediately
    !  - a cyclic 1 s timer refreshes a watchdog output
    !  - a single-shot timer supervises the cycle time
    !  - the spindle overload input is only watched while deburring
    ! All traps share bookkeeping through INTNO.

    VAR intnum irCurtain;
    VAR intnum irWatchdog;
    VAR intnum irCycleTimeout;
    VAR intnum irOverload;
    VAR num nTrapCount{4}:=[0,0,0,0];
    VAR bool bCycleTooLong:=FALSE;

    VAR signaldi di_light_curtain;
    VAR signaldi di_spindle_overload;
    VAR signaldo do_spindle_on;
    VAR signaldo do_watchdog;
    VAR signalai ai_spindle_current;

    PERS tooldata tSpindle:=[TRUE,[[0,0,210],[1,0,0,0]],[8.5,[0,0,95],[1,0,0,0],0.1,0.1,0.05]];
    CONST robtarget pEdgeStart:=[[700,-200,300],[0,0.707107,0.707107,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pEdgeEnd:=[[700,200,300],[0,0.707107,0.707107,0],[0,-1,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        setup_interrupts;
        FOR part FROM 1 TO 20 DO
            deburr_edge;
        ENDFOR
        remove_interrupts;
    ENDPROC

    PROC setup_interrupts()
        AliasIO "diLightCurtain",di_light_curtain;
        AliasIO "diSpindleOverload",di_spindle_overload;
        AliasIO "doSpindleOn",do_spindle_on;
        AliasIO "doWatchdog",do_watchdog;
        AliasIO "aiSpindleCurrent",ai_spindle_current;
        ! Remove old connections first (survive PP to main)
        remove_interrupts;
        CONNECT irCurtain WITH trap_safety;
        CONNECT irWatchdog WITH trap_watchdog;
        CONNECT irCycleTimeout WITH trap_cycle_timeout;
        CONNECT irOverload WITH trap_safety;
        ISignalDI di_light_curtain,0,irCurtain;
        ITimer 1,irWatchdog;
        ISignalDI\Single,di_spindle_overload,high,irOverload;
        ! Overload supervision is off until the spindle runs
        ISleep irOverload;
    ENDPROC

    PROC remove_interrupts()
        IDelete irCurtain;
        IDelete irWatchdog;
        IDelete irCycleTimeout;
        IDelete irOverload;
    ENDPROC

    PROC deburr_edge()
        bCycleTooLong:=FALSE;
        ITimer\Single,45,irCycleTimeout;
        MoveJ Offs(pEdgeStart,0,0,100),v1000,z20,tSpindle;
        MoveL pEdgeStart,v200,fine,tSpindle;
        SetDO do_spindle_on,1;
        WaitTime 1;
        IWatch irOverload;
        MoveL pEdgeEnd,v40,fine,tSpindle;
        ISleep irOverload;
        SetDO do_spindle_on,0;
        ! Critical section: no trap may run while the counter is updated
        IDisable;
        nTrapCount{4}:=nTrapCount{4}+1;
        IEnable;
        MoveL Offs(pEdgeEnd,0,0,100),v1000,z20,tSpindle;
        IDelete irCycleTimeout;
        CONNECT irCycleTimeout WITH trap_cycle_timeout;
        IF bCycleTooLong TPWrite "Cycle time exceeded 45 s";
    ENDPROC

    TRAP trap_safety
        ! Shared by the light curtain and the overload interrupt
        SetDO do_spindle_on,0;
        IF INTNO=irCurtain THEN
            nTrapCount{1}:=nTrapCount{1}+1;
            TPWrite "Light curtain interrupted";
            StopMove;
            WaitDI di_light_curtain,1;
            StartMove;
        ELSEIF INTNO=irOverload THEN
            nTrapCount{2}:=nTrapCount{2}+1;
            TPWrite "Spindle overload, current "\Num:=AInput(ai_spindle_current);
        ENDIF
    ENDTRAP

    TRAP trap_watchdog
        IF DOutput(do_watchdog)=1 THEN
            Reset do_watchdog;
        ELSE
            Set do_watchdog;
        ENDIF
    ENDTRAP

    TRAP trap_cycle_timeout
        bCycleTooLong:=TRUE;
        nTrapCount{3}:=nTrapCount{3}+1;
        RETURN;
    ENDTRAP

ENDMODULE
