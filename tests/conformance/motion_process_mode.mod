MODULE motion_process_mode
    ! MotionProcessModeSet: OPTIMAL_CYCLE_TIME_MODE is the controller's default mode,
    ! the one every move is planned in, so it changes nothing. ACCURACY_MODE trades
    ! cycle time for accuracy by accelerations and tuning that are not public: execution
    ! stops there ("not supported yet") rather than run with the default's timing.
    PROC main()
        MotionProcessModeSet OPTIMAL_CYCLE_TIME_MODE;
        TPWrite "default mode";
        MotionProcessModeSet ACCURACY_MODE;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
