MODULE rec_default
    ! Components of an uninitialised record get the defaults 0, "" and FALSE
    ! (manual 1.2.2).
    RECORD part
        string name;
        num weight;
        bool ok;
        pos where;
    ENDRECORD

    PROC main()
        VAR part p;
        TPWrite "[" + p.name + "]";
        TPWrite "weight=" \Num:=p.weight;
        TPWrite "ok=" \Bool:=p.ok;
        TPWrite "where.z=" \Num:=p.where.z;
    ENDPROC
ENDMODULE
