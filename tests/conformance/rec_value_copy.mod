MODULE rec_value_copy
    ! Records have value semantics: assignment copies (manual 1.3.2).
    RECORD part
        string name;
        num weight;
    ENDRECORD

    PROC main()
        VAR part r1 := ["bolt", 2.5];
        VAR part r2;
        VAR pos p1 := [1, 2, 3];
        VAR pos p2;
        r2 := r1;
        r2.weight := 99;
        r2.name := "copy";
        TPWrite r1.name + " " + ValToStr(r1.weight);
        TPWrite r2.name + " " + ValToStr(r2.weight);
        p2 := p1;
        p2.x := 100;
        TPWrite "p1.x=" \Num:=p1.x;
        TPWrite "p2.x=" \Num:=p2.x;
        r1 := r2;
        r2.weight := 1;
        TPWrite "r1.weight=" \Num:=r1.weight;
    ENDPROC
ENDMODULE
