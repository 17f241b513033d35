MODULE motion_path_joint_limit
    ! A linear move the arm cannot follow without leaving an axis's range. From
    ! [0,0,0,45,3,0] (axis 5 nearly at the wrist singularity) the TCP goes 60 mm straight
    ! down with its orientation kept: to keep it, axes 4 and 6 turn fast and axis 4 passes
    ! its +160° limit 43 mm down (166.8° at the end; worked out by an independent
    ! inverse kinematics, tests/hand/). The only solution within the ranges there has
    ! axes 4 and 6 turned half a turn, which the arm cannot jump to: the controller
    ! stops with "50028 Joint out of range" at the move (no ERROR handler takes a
    ! motion event).
    VAR robtarget p;
    VAR jointtarget jt;
    PROC main()
        MoveAbsJ [[0,0,0,45,3,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        p := CRobT();
        TPWrite "down";
        MoveL Offs(p, 0, 0, -60), v100, fine, tool0;
        TPWrite "arrived";
    ERROR
        TPWrite "handled";
    ENDPROC
ENDMODULE
