MODULE motion_offs_reltool
    ! Offs moves a position along the axes of its object frame; RelTool along the axes
    ! of its tool frame, then turns it about the tool's x, the new y and the new z
    ! axis (motion.md 3.5: T * Trans(d) * Rx * Ry * Rz). robconf and extax pass
    ! through. Distance is the straight-line distance.
    ! down: the tool pointing down, a half turn about y, q = [0, 0, 1, 0]: its x axis
    ! is world -x, its y axis world y, its z axis world -z.
    VAR robtarget down := [[500, 0, 400], [0, 0, 1, 0], [1, 0, -1, 4], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget home := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

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
        VAR robtarget q;
        ! [500 + 10, 0 - 20, 400 + 30]; the orientation is untouched.
        q := Offs(down, 10, -20, 30);
        show "offs", q;
        TPWrite "offs conf " + ValToStr(q.robconf) + " same extax " \Bool:=(q.extax = down.extax);
        ! 100 along the tool's z (world -z): [500, 0, 300].
        show "tool z", RelTool(down, 0, 0, 100);
        ! 10 along the tool's x (world -x) and 20 along its y: [490, 20, 400].
        show "tool xy", RelTool(down, 10, 20, 0);
        ! [0,0,1,0] * [c,0,0,s] with c = s = cos 45:
        ! scalar 0*c - (0,1,0).(0,0,s) = 0; vector 0*(0,0,s) + c*(0,1,0) + (0,1,0)x(0,0,s)
        ! = (0,c,0) + (s,0,0), so [0, 0.7071, 0.7071, 0].
        q := RelTool(down, 0, 0, 0 \Rz:=90);
        show "turn z", q;
        TPWrite "turn conf " + ValToStr(q.robconf);
        ! x first, then the new y: [c,s,0,0] * [c,0,s,0] = [c*c, c*s, c*s, s*s]
        ! = [0.5, 0.5, 0.5, 0.5] (y first would give [0.5, 0.5, 0.5, -0.5]).
        show "x then y", RelTool(home, 0, 0, 0 \Rx:=90 \Ry:=90);
        ! The displacement is along the axes before the turn: [100, 0, 0].
        show "move then turn", RelTool(home, 100, 0, 0 \Rz:=90);
        ! [0,0,0] to [3,4,12]: sqrt(9 + 16 + 144) = 13.
        TPWrite "distance " \Num:=Distance([0, 0, 0], [3, 4, 12]);
        TPWrite "distance " \Num:=Distance([1, 2, 3], [1, 2, 3]);
    ENDPROC
ENDMODULE
