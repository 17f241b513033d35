MODULE rec_user_record
    ! A user RECORD (manual 1.2.1), initialised with an aggregate.
    RECORD part
        string name;
        num weight;
        bool ok;
    ENDRECORD

    PROC main()
        VAR part p1 := ["bolt", 2.5, TRUE];
        TPWrite "name=" + p1.name;
        TPWrite "weight=" \Num:=p1.weight;
        TPWrite "ok=" \Bool:=p1.ok;
        p1.weight := p1.weight * 2;
        p1.name := p1.name + "s";
        TPWrite "name=" + p1.name;
        TPWrite "weight=" \Num:=p1.weight;
        p1 := ["nut", 0.5, FALSE];
        TPWrite "name=" + p1.name;
        TPWrite "ok=" \Bool:=p1.ok;
    ENDPROC
ENDMODULE
