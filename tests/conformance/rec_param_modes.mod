MODULE rec_param_modes
    ! A record passed as IN is a copy; as VAR it is the caller's variable
    ! (manual 1.1.5, parameters).
    RECORD part
        string name;
        num weight;
    ENDRECORD

    PROC changeCopy(part p)
        p.weight := 0;
        TPWrite "in copy=" \Num:=p.weight;
    ENDPROC

    PROC changeVar(VAR part p)
        p.weight := p.weight + 10;
    ENDPROC

    PROC main()
        VAR part r := ["bolt", 5];
        changeCopy r;
        TPWrite "after IN=" \Num:=r.weight;
        changeVar r;
        TPWrite "after VAR=" \Num:=r.weight;
    ENDPROC
ENDMODULE
