MODULE cmp_records
    ! = and <> compare whole records component by component (manual 1.3.1:
    ! any value type, operands of equal type).
    RECORD part
        string name;
        num weight;
    ENDRECORD

    PROC main()
        VAR pos p1 := [1, 2, 3];
        VAR pos p2 := [1, 2, 3];
        VAR pos p3 := [1, 2, 4];
        VAR orient o1 := [1, 0, 0, 0];
        VAR orient o2 := [1, 0, 0, 0];
        VAR part r1 := ["bolt", 2.5];
        VAR part r2 := ["bolt", 2.5];
        VAR part r3 := ["nut", 2.5];
        TPWrite "a=" \Bool:=p1 = p2;
        TPWrite "b=" \Bool:=p1 <> p2;
        TPWrite "c=" \Bool:=p1 = p3;
        TPWrite "d=" \Bool:=p1 <> p3;
        TPWrite "e=" \Bool:=o1 = o2;
        TPWrite "f=" \Bool:=r1 = r2;
        TPWrite "g=" \Bool:=r1 = r3;
        TPWrite "h=" \Bool:=r1 <> r3;
        TPWrite "i=" \Bool:=p1 = [1, 2, 3];
    ENDPROC
ENDMODULE
