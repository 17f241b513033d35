MODULE motion_pdisp
    ! PDispSet, PDispOff, EOffsSet, EOffsOff read back through C_PROGDISP (manual 1.7),
    ! and ORobT, which takes a position out of the displacement frame (robot part:
    ! object = pdisp * point) and adds the external axis offsets back (axis =
    ! programmed + offset); \InPDisp removes only the offsets, \InEOffs only the
    ! displacement (ORobT page). Unused axes (9E9) keep their mark (uncertain).
    ! The displacement below is a turn of 90 degrees about z, q = [cos 45, 0, 0, sin 45],
    ! and a shift of 100 along x: [x, y, z] -> [100 - y, x, z].
    VAR robtarget p := [[10, 20, 30], [1, 0, 0, 0], [0, 0, 0, 0], [1, 2, 9E9, 9E9, 9E9, 9E9]];

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
        TPWrite label + " " + rpos(t.trans) + " " + rori(t.rot) + " eax " + ValToStr(t.extax.eax_a) + "," + ValToStr(t.extax.eax_b) + " unused " + ValToStr(t.extax.eax_c = 9E9);
    ENDPROC

    PROC main()
        VAR robtarget q;
        TPWrite "default " + ValToStr(C_PROGDISP);
        ! With no displacement and no offsets ORobT changes nothing.
        q := ORobT(p);
        TPWrite "unchanged " \Bool:=(q = p);
        PDispSet [[100, 0, 0], [0.7071068, 0, 0, 0.7071068]];
        TPWrite "pdisp " + rpos(C_PROGDISP.pdisp.trans) + " " + rori(C_PROGDISP.pdisp.rot);
        EOffsSet [10, 20, 0, 0, 0, 0];
        TPWrite "eoffs " + ValToStr(C_PROGDISP.eoffs);
        ! [10, 20, 30] -> [100 - 20, 10, 30] = [80, 10, 30]; rot = q_disp * [1,0,0,0];
        ! eax_a = 1 + 10, eax_b = 2 + 20.
        show "orobt", ORobT(p);
        show "inpdisp", ORobT(p \InPDisp);
        show "ineoffs", ORobT(p \InEOffs);
        PDispOff;
        TPWrite "off " + ValToStr(C_PROGDISP.pdisp);
        show "no pdisp", ORobT(p);
        EOffsOff;
        TPWrite "off " + ValToStr(C_PROGDISP.eoffs);
        show "nothing", ORobT(p);
    ENDPROC
ENDMODULE
