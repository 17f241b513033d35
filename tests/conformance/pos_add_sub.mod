MODULE pos_add_sub
    ! Vector addition and subtraction of pos (manual 1.3.1).
    PROC show(string label, pos p)
        TPWrite label + "=" + ValToStr(p.x) + "," + ValToStr(p.y) + "," + ValToStr(p.z);
    ENDPROC

    PROC main()
        VAR pos p1 := [1, 2, 3];
        VAR pos p2 := [10, 20, 30];
        VAR pos r;
        r := p1 + p2;
        show "sum", r;
        r := p2 - p1;
        show "diff", r;
        r := p1 - p2;
        show "neg", r;
        r := p1 + p2 - p1;
        show "back", r;
    ENDPROC
ENDMODULE
