MODULE motion_singarea_wrist
    ! SingArea\Wrist (manual 2.2.2): near a singular point a linear move interpolates
    ! the wrist axes axis by axis while the TCP keeps its line. From [0,0,0,45,3,0]
    ! (axis 5 near the wrist singularity) 60 mm straight down: keeping the orientation
    ! would take axis 4 past its 160° limit (motion_path_joint_limit). With \Wrist the
    ! wrist goes from [45, 3, 0] to the end's solution within the ranges nearest the
    ! start, [-13.24, -9.30, 58.03] (tests/hand/path_joint_limit.py, the other wrist
    ! branch of [166.76, 9.30, -121.97]), slowly enough for its axes, so the TCP keeps
    ! v100: 60/100 + 100/10000 = 0.61 s, + 0.05 s settle at the fine point. Back at the
    ! start with SingArea\Off, the same move is refused: 50028 for axis 4. ConfL\Off:
    ! the end's configuration is not the start's (axis 4 below 0, axis 5 turned over).
    VAR clock c;
    VAR robtarget p;
    VAR jointtarget jt;
    PROC main()
        MoveAbsJ [[0,0,0,45,3,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        p := CRobT();
        ConfL \Off;
        SingArea \Wrist;
        ClkStart c;
        MoveL Offs(p, 0, 0, -60), v100, fine, tool0;
        TPWrite "t " + NumToStr(ClkRead(c), 2);
        jt := CJointT();
        TPWrite "axis 4 " \Num:=Round(jt.robax.rax_4 \Dec:=1);
        TPWrite "axis 5 " \Num:=Round(jt.robax.rax_5 \Dec:=1);
        MoveAbsJ [[0,0,0,45,3,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        SingArea \Off;
        MoveL Offs(p, 0, 0, -60), v100, fine, tool0;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
