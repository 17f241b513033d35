MODULE Guide
    ! Joint guidance by an external sensor over UdpUc, as the EGM application
    ! manual's RAPID reference describes it.
    VAR egmident sensor_id;
    CONST egm_minmax settled := [-0.1, 0.1];
    CONST jointtarget start := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveAbsJ start, v200, fine, tool0;
        EGMReset sensor_id;
        EGMGetId sensor_id;
        EGMSetupUC ROB_1, sensor_id, "default", "UCdevice" \Joint \CommTimeout:=10;
        EGMActJoint sensor_id \J1:=settled \J2:=settled \J3:=settled \SampleRate:=4;
        EGMRunJoint sensor_id, EGM_STOP_HOLD \J1 \J2 \J3 \CondTime:=20 \RampInTime:=0.05;
        IF EGMGetState(sensor_id) = EGM_STATE_CONNECTED THEN
            TPWrite "guidance ended";
        ENDIF
        EGMReset sensor_id;
    ENDPROC
ENDMODULE
