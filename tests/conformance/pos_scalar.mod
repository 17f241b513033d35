MODULE pos_scalar
    ! Scalar multiplication (num * pos, pos * num), pos / num and unary
    ! minus / plus on pos (manual 1.3.1).
    PROC show(string label, pos p)
        TPWrite label + "=" + ValToStr(p.x) + "," + ValToStr(p.y) + "," + ValToStr(p.z);
    ENDPROC

    PROC main()
        VAR pos p := [1, 2, 3];
        VAR pos r;
        r := 2 * p;
        show "twice", r;
        r := p * 3;
        show "thrice", r;
        r := p / 2;
        show "half", r;
        r := -p;
        show "minus", r;
        r := +p;
        show "plus", r;
        r := (p + p) / 4;
        show "quarter", r;
    ENDPROC
ENDMODULE
