MODULE motion_corr_reach
    ! A correction that puts the path out of the robot's reach stops execution with
    ! the controller's motion error (50050 Position outside reach), never a NaN. The
    ! path coordinate system's z is the tool's z axis (corr.rs): with the tool pointing
    ! down, +2000 mm there is 2000 mm below the path, z = -1600 for the IRB 120
    ! (reach 580 mm). The same move without \Corr is fine.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR corrdescr c;
    PROC main()
        MoveJ p0, v1000, fine, tool0;
        CorrCon c;
        CorrWrite c, [0, 0, 2000];
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        TPWrite "uncorrected move done";
        MoveL p0, v100, fine, tool0 \Corr;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
