MODULE pos_components
    ! Record components of predefined types (pos, pose, robtarget).
    PROC main()
        VAR pos p;
        VAR pose fr;
        VAR robtarget rt;
        p.x := 5;
        p.y := p.x * 2;
        TPWrite "p.y=" \Num:=p.y;
        TPWrite "p.z=" \Num:=p.z;
        fr.trans := [10, 20, 30];
        fr.trans.x := fr.trans.x + 1;
        fr.rot := [1, 0, 0, 0];
        TPWrite "fr.trans.x=" \Num:=fr.trans.x;
        TPWrite "fr.rot.q1=" \Num:=fr.rot.q1;
        rt.trans := fr.trans;
        rt.trans.z := 300;
        rt.robconf.cf4 := -1;
        TPWrite "rt.trans.y=" \Num:=rt.trans.y;
        TPWrite "rt.trans.z=" \Num:=rt.trans.z;
        TPWrite "cf4=" \Num:=rt.robconf.cf4;
        TPWrite "fr.trans.z=" \Num:=fr.trans.z;
    ENDPROC
ENDMODULE
