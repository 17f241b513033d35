MODULE motion_mirpos
    ! MirPos mirrors a position in the xy plane of MirPlane's object frame (uframe *
    ! oframe). The tool frame's x and z axes are mirrored and y follows (right-handed);
    ! with \MirY, y and z are mirrored and x follows (MirPos page). Point is in \WObj's
    ! object frame, world without it, and so is the result.
    VAR robtarget p := [[100, 200, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    ! The world xy plane.
    VAR wobjdata floor := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
    ! The plane z = 100 (object frame 100 above the user frame).
    VAR wobjdata shelf := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 100], [1, 0, 0, 0]]];
    ! The world xz plane: the object frame turned 90 degrees about x.
    VAR wobjdata wall := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [0.7071068, 0.7071068, 0, 0]]];
    ! A work object 500 above the world.
    VAR wobjdata table := [FALSE, TRUE, "", [[0, 0, 500], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];

    FUNC string rpos(pos v)
        VAR pos r;
        r := [Round(v.x \Dec:=3), Round(v.y \Dec:=3), Round(v.z \Dec:=3)];
        RETURN ValToStr(r);
    ENDFUNC

    FUNC string rori(orient q)
        VAR orient r;
        r := [Round(q.q1 \Dec:=4), Round(q.q2 \Dec:=4), Round(q.q3 \Dec:=4), Round(q.q4 \Dec:=4)];
        RETURN ValToStr(r);
    ENDFUNC

    PROC show(string label, robtarget t)
        TPWrite label + " " + rpos(t.trans) + " " + rori(t.rot);
    ENDPROC

    PROC main()
        ! z -> -z. Axes x = (1,0,0), z mirrored = (0,0,-1), y = z x x = (0,-1,0): the
        ! matrix diag(1,-1,-1), a half turn about x, q = [0, 1, 0, 0].
        show "floor", MirPos(p, floor);
        ! \MirY: y = (0,1,0), z = (0,0,-1), x = y x z = (-1,0,0): diag(-1,1,-1), a half
        ! turn about y, q = [0, 0, 1, 0].
        show "floor mir y", MirPos(p, floor \MirY);
        ! z = 300 is 200 above the plane z = 100, so it goes to 100 - 200 = -100.
        show "shelf", MirPos(p, shelf);
        ! In the xz plane y -> -y. x = (1,0,0) and z = (0,0,1) lie in the plane and stay;
        ! y = z x x = (0,1,0): the orientation is unchanged.
        show "wall", MirPos(p, wall);
        ! p in table is 800 above the world; mirrored to -800, which is -1300 in table.
        show "table", MirPos(p, floor \WObj:=table);
    ENDPROC
ENDMODULE
