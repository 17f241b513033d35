MODULE motion_calib_tcp
    ! MToolTCPCalib and MToolRotCalib (manual 1.18) on an IRB 120. The four approach
    ! positions are made with the true tool `truth`: its TCP on one fixed tip P in four
    ! orientations, turned into axis values by CalcJointT. The calibration starts from
    ! a tool with no TCP and must find truth's TCP again, [10,-5,120], with MaxErr and
    ! MeanErr 0 (to the 0.01 mm printed). Orientations: pointing down (OrientZYX
    ! 0,180,0) and tilted 20 degrees from it about y and both ways about x: turns
    ! about two axes, so the TCP is fixed.
    PERS tooldata truth := [TRUE, [[10, -5, 120], [0.965926, 0, 0.258819, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
    PERS tooldata calib := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
    CONST pos tip := [350, 0, 250];

    FUNC num r2(num x)
        ! Rounded to 0.01; adding 0 turns a -0 into 0.
        RETURN Round(x \Dec:=2) + 0;
    ENDFUNC

    FUNC string d4(num x)
        RETURN NumToStr(Round(x \Dec:=4) + 0, 4);
    ENDFUNC

    FUNC pos rnd(pos p)
        RETURN [r2(p.x), r2(p.y), r2(p.z)];
    ENDFUNC

    FUNC jointtarget at(orient o)
        RETURN CalcJointT([tip, o, [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], truth);
    ENDFUNC

    PROC main()
        VAR jointtarget j1;
        VAR jointtarget j2;
        VAR jointtarget j3;
        VAR jointtarget j4;
        VAR jointtarget jz;
        VAR jointtarget jx;
        VAR robtarget rt;
        VAR num maxerr;
        VAR num meanerr;
        ConfJ \Off;
        j1 := at(OrientZYX(0, 180, 0));
        j2 := at(OrientZYX(0, 200, 0));
        j3 := at(OrientZYX(0, 180, 20));
        j4 := at(OrientZYX(0, 180, -20));
        MToolTCPCalib j1, j2, j3, j4, calib, maxerr, meanerr;
        TPWrite "tcp " \Pos:=rnd(calib.tframe.trans);
        TPWrite "max " \Num:=r2(maxerr);
        TPWrite "mean " \Num:=r2(meanerr);
        ! The orientation was not touched; the load was not either.
        TPWrite "rot kept " \Bool:=calib.tframe.rot = [1, 0, 0, 0];
        TPWrite "load kept " \Num:=calib.tload.mass;
        ! MToolRotCalib: at j1 the TCP touches the tip; backing the TCP 50 mm along the
        ! tool's own -z (RelTool 0,0,-50) puts the tip on its +z axis, backing 40 mm
        ! along -x puts it on its +x axis. truth's tool frame is turned 30 degrees about
        ! the flange's y axis: orient [cos 15, 0, sin 15, 0] = [0.9659, 0, 0.2588, 0].
        rt := CalcRobT(j1, truth);
        jz := CalcJointT(RelTool(rt, 0, 0, -50), truth);
        jx := CalcJointT(RelTool(rt, -40, 0, 0), truth);
        MToolRotCalib j1, jz \XPos:=jx, calib;
        TPWrite "rot " + d4(calib.tframe.rot.q1) + " " + d4(calib.tframe.rot.q2) + " " + d4(calib.tframe.rot.q3) + " " + d4(calib.tframe.rot.q4);
        TPWrite "tcp kept " \Pos:=rnd(calib.tframe.trans);
        ! Without \XPos, x is the flange's x made square to the new z. The tool's z in
        ! the flange is (sin 30, 0, cos 30); flange x minus its part along z is
        ! (0.75, 0, -0.433), which is the tool's own x (cos 30, 0, -sin 30): the same.
        calib.tframe.rot := [1, 0, 0, 0];
        MToolRotCalib j1, jz, calib;
        TPWrite "rot without XPos " + d4(calib.tframe.rot.q1) + " " + d4(calib.tframe.rot.q3);
        ! One approach 1 mm off: the residual of the least-squares fit is the part of
        ! that 1 mm error no TCP explains, so the four errors have a root sum of
        ! squares of at most 1 mm: MaxErr <= 1, MeanErr <= 2/4 = 0.5, and not 0.
        j3 := CalcJointT([[351, 0, 250], OrientZYX(0, 180, 20), [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], truth);
        MToolTCPCalib j1, j2, j3, j4, calib, maxerr, meanerr;
        TPWrite "noisy max > 0.01 " \Bool:=maxerr > 0.01;
        TPWrite "noisy max <= 1 " \Bool:=maxerr <= 1.0001;
        TPWrite "noisy mean <= 0.5 " \Bool:=meanerr <= 0.5001;
    ENDPROC
ENDMODULE
