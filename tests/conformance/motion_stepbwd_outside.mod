MODULE motion_stepbwd_outside
    ! StepBwdPath belongs in a RESTART event routine (manual: StepBwdPath); called
    ! from main, execution stops.
    PROC main()
        MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        TPWrite "before";
        StepBwdPath 30, 1;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
