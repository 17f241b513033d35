MODULE motion_servo_settings
    ! Servo and supervision settings (manual 1.7, 1.8): MotionSup, SoftAct/SoftDeact,
    ! TuneServo/TuneReset, ActEventBuffer/DeactEventBuffer, SpeedLimAxis,
    ! SpeedLimCheckPoint, PFRestart. They keep their state and check their arguments;
    ! none changes the simulated motion (no collisions to supervise, a servo that
    ! follows its path exactly, an event preset time of 0, and no LimitSpeed system
    ! input for the speed limits), so the same move takes the same time with all of
    ! them set.
    CONST jointtarget a := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget b := [[60, -20, 10, 30, 60, 90], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR num stage := 0;

    PROC main()
        VAR clock c;
        VAR num plain;
        VAR num tuned;
        MoveAbsJ a, v1000, fine, tool0;
        ClkStart c;
        MoveAbsJ b, v1000, fine, tool0;
        ClkStop c;
        plain := ClkRead(c);
        MoveAbsJ a, v1000, fine, tool0;
        ! C_MOTSET shows motion supervision and the event buffer (motsetdata:
        ! motionsup, tunevalue, evtbufferact).
        TPWrite "default " + ValToStr(C_MOTSET.motionsup) + " " + ValToStr(C_MOTSET.tunevalue) + " " + ValToStr(C_MOTSET.evtbufferact);
        MotionSup \On \TuneValue:=200;
        TPWrite "tuned " + ValToStr(C_MOTSET.motionsup) + " " + ValToStr(C_MOTSET.tunevalue);
        MotionSup \Off;
        TPWrite "off " + ValToStr(C_MOTSET.motionsup) + " " + ValToStr(C_MOTSET.tunevalue);
        ! With no switch, \On; without \TuneValue, the configured level (100 %).
        MotionSup;
        TPWrite "on again " + ValToStr(C_MOTSET.motionsup) + " " + ValToStr(C_MOTSET.tunevalue);
        SoftAct 3, 20;
        SoftAct \MechUnit:=ROB_1, 5, 100 \Ramp:=150;
        TuneServo ROB_1, 1, 110;
        TuneServo ROB_1, 2, 90 \Type:=TUNE_KP;
        DeactEventBuffer;
        TPWrite "event buffer " \Bool:=C_MOTSET.evtbufferact;
        SpeedLimAxis ROB_1, 1, 30;
        SpeedLimCheckPoint 250;
        ClkReset c;
        ClkStart c;
        MoveAbsJ b, v1000, fine, tool0;
        ClkStop c;
        tuned := ClkRead(c);
        TPWrite "same time " \Bool:=tuned = plain;
        SoftDeact;
        SoftDeact \Ramp:=200;
        TuneReset;
        ActEventBuffer;
        TPWrite "event buffer " \Bool:=C_MOTSET.evtbufferact;
        TPWrite "power failure " \Bool:=PFRestart();
        TPWrite "power failure, base level " \Bool:=PFRestart(\Base);
        ! The error paths, each handled and skipped.
        stage := 1;
        MotionSup \TuneValue:=0;
        stage := 2;
        MotionSup \TuneValue:=301;
        stage := 3;
        SoftAct 2, 101;
        stage := 4;
        SoftAct 2, 50 \Ramp:=99;
        stage := 5;
        SoftAct 0, 50;
        stage := 6;
        TuneServo ROB_1, 1, 0;
        stage := 7;
        TuneServo ROB_1, 1, 100 \Type:=11;
        stage := 8;
        SpeedLimAxis ROB_1, 7, 30;
        stage := 9;
        SpeedLimAxis ROB_1, 1, 0;
        stage := 10;
        SpeedLimCheckPoint -5;
        TPWrite "done";
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "stage " + NumToStr(stage, 0) + ": ERR_ARGVALERR";
            TRYNEXT;
        ELSEIF ERRNO = ERR_AXIS_PAR THEN
            TPWrite "stage " + NumToStr(stage, 0) + ": ERR_AXIS_PAR";
            TRYNEXT;
        ELSEIF ERRNO = ERR_SPEEDLIM_VALUE THEN
            TPWrite "stage " + NumToStr(stage, 0) + ": ERR_SPEEDLIM_VALUE";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
