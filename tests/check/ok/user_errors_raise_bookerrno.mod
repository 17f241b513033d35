MODULE user_errors_raise_bookerrno
    ! Application errors of the screwing station.
    ! User error numbers 1..90 are raised with RAISE, booked system
    ! numbers with BookErrNo. The main routine is the recovery point
    ! for every error (long jump) thanks to ERROR (LONG_JMP_ALL_ERR).

    ! Plain user error numbers (range 1..90)
    CONST errnum ERR_NO_SCREW:=10;
    CONST errnum ERR_TORQUE_LOW:=11;
    CONST errnum ERR_TORQUE_HIGH:=12;
    ! Booked error numbers, must be initialised to -1
    VAR errnum errFeederJam:=-1;
    VAR errnum errSpindleFault:=-1;

    VAR num nTorque:=0;
    VAR num nScrewsDone:=0;
    VAR num nRecoveries:=0;
    VAR bool bFeederOk:=TRUE;

    VAR signaldi di_screw_present;
    VAR signalai ai_torque;
    VAR signaldo do_feeder_reset;

    PROC main()
        AliasIO "diScrewPresent",di_screw_present;
        AliasIO "aiTorque",ai_torque;
        AliasIO "doFeederReset",do_feeder_reset;
        BookErrNo errFeederJam;
        BookErrNo errSpindleFault;
        FOR hole FROM 1 TO 6 DO
            screw_hole hole;
        ENDFOR
        TPWrite "Screws done: "\Num:=nScrewsDone;
    ERROR (LONG_JMP_ALL_ERR)
        ! Recovery point: errors from deep inside screw_hole end up here
        nRecoveries:=nRecoveries+1;
        IF ERRNO=errFeederJam THEN
            PulseDO\PLength:=0.5,do_feeder_reset;
            bFeederOk:=TRUE;
            RETRY;
        ELSEIF ERRNO=errSpindleFault THEN
            ErrWrite "Spindle fault","Spindle reported a fault during screwing"\RL2:="Station stopped";
            EXIT;
        ENDIF
        TRYNEXT;
    ENDPROC

    PROC screw_hole(num hole)
        feed_screw;
        run_spindle hole;
        check_torque;
        nScrewsDone:=nScrewsDone+1;
    ERROR
        IF ERRNO=ERR_TORQUE_LOW THEN
            ! Re-tighten once
            run_spindle hole;
            TRYNEXT;
        ELSEIF ERRNO=ERR_NO_SCREW THEN
            WaitTime 1;
            RETRY;
        ENDIF
        ! Anything else goes to the caller
        RAISE;
    ENDPROC

    PROC feed_screw()
        IF NOT bFeederOk RAISE errFeederJam;
        IF di_screw_present=0 THEN
            RAISE ERR_NO_SCREW;
        ENDIF
    ENDPROC

    PROC run_spindle(num hole)
        IF hole<1 OR hole>6 THEN
            RAISE errSpindleFault;
        ENDIF
        WaitTime 0.8;
        nTorque:=AInput(ai_torque);
    ENDPROC

    PROC check_torque()
        IF nTorque<4.5 THEN
            RAISE ERR_TORQUE_LOW;
        ELSEIF nTorque>6 THEN
            RAISE ERR_TORQUE_HIGH;
        ENDIF
    ERROR
        IF ERRNO=ERR_TORQUE_HIGH THEN
            TPWrite "Torque too high: "\Num:=nTorque;
            ! Log it and carry on with the next hole
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! A PLC fault code is passed on as error number; codes outside
    ! 1..90 turn into ERR_ILLRAISE in the handler
    PROC raise_plc_fault(num code)
        RAISE code;
    ERROR
        IF ERRNO=ERR_ILLRAISE THEN
            TPWrite "PLC fault code out of range: "\Num:=code;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
