MODULE motion_calib_frames
    ! Stationary tools and rotation axes (manual 1.18), from robtargets worked out by
    ! hand.
    PERS tooldata stool := [FALSE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 0], [1, 0, 0, 0], 0, 0, 0]];
    ! SToolTCPCalib: a pointer 150 mm along the flange's z axis touches the stationary
    ! TCP W = [600, 100, 400] in four orientations; each robtarget is the flange, at
    ! W - R*[0, 0, 150]: pointing down (z to -z) it is 150 above W; turned 90 degrees
    ! about y (z to +x) 150 behind W in x; 90 about x (z to -y) 150 beyond W in y;
    ! -90 about y (z to -x) 150 ahead of W in x.
    CONST robtarget p1 := [[600, 100, 550], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p2 := [[450, 100, 400], [0.707107, 0, 0.707107, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p3 := [[600, 250, 400], [0.707107, 0.707107, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p4 := [[750, 100, 400], [0.707107, 0, -0.707107, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    ! SToolRotCalib: the pointer at the TCP, 100 mm below it on its z axis, and at a
    ! point ahead in x and a little higher (made square to z, that is +x).
    CONST robtarget tcp := [[600, 100, 400], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget zp := [[600, 100, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget xp := [[700, 100, 420], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    FUNC num r2(num x)
        ! Rounded to 0.01; adding 0 turns a -0 into 0.
        RETURN Round(x \Dec:=2) + 0;
    ENDFUNC

    FUNC pos rnd(pos p)
        RETURN [r2(p.x), r2(p.y), r2(p.z)];
    ENDFUNC

    ! Where a rotation takes a unit vector (the axes of a frame, whatever the
    ! quaternion's sign).
    FUNC pos turned(orient o, pos v)
        RETURN rnd(PoseVect([[0, 0, 0], o], v));
    ENDFUNC

    PROC main()
        VAR num maxerr;
        VAR num meanerr;
        VAR robtarget circle{5};
        VAR pose axis;
        SToolTCPCalib p1, p2, p3, p4, stool, maxerr, meanerr;
        TPWrite "stationary tcp " \Pos:=rnd(stool.tframe.trans);
        TPWrite "max " \Num:=r2(maxerr);
        TPWrite "mean " \Num:=r2(meanerr);
        SToolRotCalib tcp, zp, xp, stool;
        TPWrite "tcp " \Pos:=rnd(stool.tframe.trans);
        TPWrite "z " \Pos:=turned(stool.tframe.rot, [0, 0, 1]);
        TPWrite "x " \Pos:=turned(stool.tframe.rot, [1, 0, 0]);
        ! y = z x x = [0,0,-1] x [1,0,0] = [0,-1,0].
        TPWrite "y " \Pos:=turned(stool.tframe.rot, [0, 1, 0]);
        ! A turntable: points at radius 200 round [800, 0, 300] in a level plane, at
        ! 0, 30, 90 and 150 degrees anticlockwise seen from above (200 cos 30 =
        ! 173.205): the axis is world z, up, as the points turn positively about it;
        ! x points to the first point: the frame is [800, 0, 300] with no rotation.
        circle{1} := [[1000, 0, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        circle{2} := [[973.205, 100, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        circle{3} := [[800, 200, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        circle{4} := [[626.795, 100, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        circle{5} := [[800, -200, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        axis := CalcRotAxisFrame(ROB_1, circle, 4, maxerr, meanerr);
        TPWrite "axis origin " \Pos:=rnd(axis.trans);
        TPWrite "axis z " \Pos:=turned(axis.rot, [0, 0, 1]);
        TPWrite "axis x " \Pos:=turned(axis.rot, [1, 0, 0]);
        TPWrite "axis max " \Num:=r2(maxerr);
        ! Five points: the fifth (270 degrees) is on the circle too.
        axis := CalcRotAxisFrame(ROB_1, circle, 5, maxerr, meanerr);
        TPWrite "five max " \Num:=r2(maxerr);
        ! CalcRotAxFrameZ: z to the side of a point below the plane: down; x still to
        ! the first point, so y = [0,0,-1] x [1,0,0] = [0,-1,0].
        axis := CalcRotAxFrameZ(circle, 4, [[800, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], maxerr, meanerr);
        TPWrite "z axis z " \Pos:=turned(axis.rot, [0, 0, 1]);
        TPWrite "z axis y " \Pos:=turned(axis.rot, [0, 1, 0]);
        TPWrite "z axis origin " \Pos:=rnd(axis.trans);
        ! A point 1 mm above the plane: its own error is what the fit cannot explain,
        ! at most 1 mm.
        circle{3}.trans.z := 301;
        axis := CalcRotAxisFrame(ROB_1, circle, 4, maxerr, meanerr);
        TPWrite "lifted max in (0.01, 1] " \Bool:=maxerr > 0.01 AND maxerr <= 1.0001;
        TPWrite "lifted mean <= max " \Bool:=meanerr <= maxerr;
    ENDPROC
ENDMODULE
