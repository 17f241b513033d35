MODULE motion_frames
    ! DefFrame: x axis from NewP1 towards NewP2, NewP3 in the xy plane on the +y side;
    ! \Origin 1 (default) puts the origin in NewP1, 2 in NewP2, 3 on the x axis where
    ! NewP3 is on the y axis (DefFrame page). DefDFrame: the displacement taking the
    ! three old points to the new ones. DefAccFrame: the least-squares frame taking
    ! TargetListOne to TargetListTwo, with the largest and mean error (DefAccFrame page).
    VAR robtarget t := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

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

    PROC show(string label, pose f)
        TPWrite label + " " + rpos(f.trans) + " " + rori(f.rot);
    ENDPROC

    FUNC robtarget at(num x, num y, num z)
        RETURN Offs(t, x, y, z);
    ENDFUNC

    PROC main()
        VAR robtarget one{5};
        VAR robtarget two{5};
        VAR num max_err;
        VAR num mean_err;
        VAR pose f;
        ! x = (100,100,0) - (100,0,0) = (0,100,0) -> (0,1,0); z = x cross (p3 - p1) =
        ! (0,1,0) x (-100,50,0) = (0,0,100) -> (0,0,1); y = z x x = (-1,0,0). That is a
        ! quarter turn about z, q = [cos 45, 0, 0, sin 45].
        show "frame", DefFrame(at(100, 0, 0), at(100, 100, 0), at(0, 50, 0));
        show "origin 2", DefFrame(at(100, 0, 0), at(100, 100, 0), at(0, 50, 0) \Origin:=2);
        ! p1 + x * (x . (p3 - p1)) = (100,0,0) + (0,1,0) * 50.
        show "origin 3", DefFrame(at(100, 0, 0), at(100, 100, 0), at(0, 50, 0) \Origin:=3);
        ! Old points: the world axes. New points: turned a quarter about z, moved 500
        ! along x: (x,y,z) -> (500 - y, x, z).
        show "dframe", DefDFrame(at(0, 0, 0), at(100, 0, 0), at(0, 100, 0), at(500, 0, 0), at(500, 100, 0), at(400, 0, 0));
        ! The same motion fitted from four pairs: exact, so both errors are 0.
        one{1} := at(0, 0, 0);
        one{2} := at(100, 0, 0);
        one{3} := at(0, 100, 0);
        one{4} := at(0, 0, 100);
        two{1} := at(500, 0, 0);
        two{2} := at(500, 100, 0);
        two{3} := at(400, 0, 0);
        two{4} := at(500, 0, 100);
        f := DefAccFrame(one, two, 4, max_err, mean_err);
        show "acc exact", f;
        TPWrite "errors " + ValToStr(Round(max_err \Dec:=3)) + " " + ValToStr(Round(mean_err \Dec:=3));
        ! A square and its centre (centroid (50,50,0)), moved along z by +1 at the
        ! corners and -4 at the centre. The moves sum to 0 and their first moments
        ! about the centroid (x: -50+50-50+50, y: -50-50+50+50) are 0, so no shift or
        ! turn fits them better than none: the frame is the identity, the errors are
        ! 1, 1, 1, 1, 4: largest 4, mean 8 / 5 = 1.6.
        one{1} := at(0, 0, 0);
        one{2} := at(100, 0, 0);
        one{3} := at(0, 100, 0);
        one{4} := at(100, 100, 0);
        one{5} := at(50, 50, 0);
        two{1} := at(0, 0, 1);
        two{2} := at(100, 0, 1);
        two{3} := at(0, 100, 1);
        two{4} := at(100, 100, 1);
        two{5} := at(50, 50, -4);
        f := DefAccFrame(one, two, 5, max_err, mean_err);
        show "acc fit", f;
        TPWrite "errors " + ValToStr(Round(max_err \Dec:=3)) + " " + ValToStr(Round(mean_err \Dec:=3));
    ENDPROC
ENDMODULE
