MODULE motion_singarea_lockaxis4
    ! SingArea \LockAxis4 (axis 4 held at 0° or ±180° on linear and circular moves) is
    ! kept as a setting, but `rapid run` does not model it: a linear move under it stops
    ! execution with a message naming it, rather than moving as if it were \Off. Joint
    ! moves are not affected by SingArea.
    PROC main()
        SingArea \LockAxis4;
        MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        TPWrite "joint move made";
        MoveL Offs(CRobT(), 0, 0, -20), v100, fine, tool0;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
