MODULE motion_pdisp_on
    ! PDispOn, EOffsOn, CTool, CWObj after a move (hand-worked: the displacement is the
    ! actual position minus ProgPoint, translation only without \Rot).
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    PERS tooldata pen := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [0.5, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];

    PROC main()
        VAR tooldata t;
        VAR wobjdata w;
        MoveJ p0, v1000, fine, pen;
        ! The move made pen the active tool.
        t := CTool();
        TPWrite "active tool length " \Num:=t.tframe.trans.z;
        w := CWObj();
        TPWrite "active wobj user frame " \Pos:=w.uframe.trans;
        ! The TCP stands at [300, 0, 400]; ProgPoint is 20 mm further in x.
        PDispOn Offs(p0, 20, 0, 0), pen;
        TPWrite "pdisp " \Pos:=C_PROGDISP.pdisp.trans;
        ! With ExeP: ExeP minus ProgPoint.
        PDispOn \ExeP:=Offs(p0, 0, 5, -2), p0, pen;
        TPWrite "pdisp " \Pos:=C_PROGDISP.pdisp.trans;
        PDispOff;
        TPWrite "pdisp " \Pos:=C_PROGDISP.pdisp.trans;
        ! External axis a: 110 at ExeP, 100 at ProgPoint: offset 10; unused axes 0.
        EOffsOn \ExeP:=[[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [110, 9E9, 9E9, 9E9, 9E9, 9E9]],
            [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [100, 9E9, 9E9, 9E9, 9E9, 9E9]];
        TPWrite "eoffs a " \Num:=C_PROGDISP.eoffs.eax_a;
        TPWrite "eoffs b " \Num:=C_PROGDISP.eoffs.eax_b;
    ENDPROC
ENDMODULE
