MODULE geometry_orient_pose
    ! OrientZYX / EulerZYX use the order Z, Y, X; a pose maps points of its frame
    ! into the outer frame (PoseVect), PoseInv undoes it, PoseMult composes.
    ! Expected values worked out with a 90 degree rotation about Z:
    ! q = [cos 45, 0, 0, sin 45]; (10,0,0) turns to (0,10,0).
    PROC main()
        VAR orient o;
        VAR pose p1 := [[100, 0, 0], [0.707107, 0, 0, 0.707107]];
        VAR pose inv;
        VAR pose both;
        VAR pos v;
        o := OrientZYX(90, 0, 0);
        TPWrite "q1 " \Bool:=Abs(o.q1 - 0.707107) < 0.00001;
        TPWrite "q2 " \Bool:=Abs(o.q2) < 0.00001;
        TPWrite "q4 " \Bool:=Abs(o.q4 - 0.707107) < 0.00001;
        TPWrite "z=" \Num:=Round(EulerZYX(\Z, o));
        TPWrite "y=" \Num:=Round(EulerZYX(\Y, OrientZYX(0, 30, 0)));
        TPWrite "x=" \Num:=Round(EulerZYX(\X, OrientZYX(10, 20, 30)));
        v := PoseVect(p1, [10, 0, 0]);
        TPWrite "vx=" \Num:=Round(v.x);
        TPWrite "vy=" \Num:=Round(v.y);
        TPWrite "vz=" \Num:=Round(v.z);
        inv := PoseInv(p1);
        TPWrite "inv y=" \Num:=Round(inv.trans.y);
        TPWrite "inv x=" \Num:=Round(inv.trans.x);
        TPWrite "inv q4 " \Bool:=Abs(inv.rot.q4 + 0.707107) < 0.00001;
        both := PoseMult(p1, inv);
        TPWrite "identity " \Bool:=Abs(both.trans.x) < 0.001 AND Abs(both.trans.y) < 0.001 AND Abs(both.rot.q1 - 1) < 0.00001;
        o := NOrient([0, 0, 0, 2]);
        TPWrite "norm q4=" \Num:=o.q4;
    ENDPROC
ENDMODULE
