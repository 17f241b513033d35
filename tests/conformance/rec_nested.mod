MODULE rec_nested
    ! Records containing records (manual 1.2.1: components may be records).
    RECORD part
        string name;
        num weight;
    ENDRECORD

    RECORD station
        string id;
        pos loc;
        part item;
    ENDRECORD

    PROC main()
        VAR station st := ["S1", [100, 200, 0], ["gear", 3]];
        VAR station st2;
        VAR pos one := [1, 1, 1];
        TPWrite "id=" + st.id;
        TPWrite "y=" \Num:=st.loc.y;
        TPWrite "item=" + st.item.name;
        st.item.weight := st.item.weight + 1;
        st.loc := st.loc + one;
        st2 := st;
        st.item.name := "shaft";
        TPWrite "w=" \Num:=st2.item.weight;
        TPWrite "x=" \Num:=st2.loc.x;
        TPWrite "st2 item=" + st2.item.name;
        TPWrite "st item=" + st.item.name;
    ENDPROC
ENDMODULE
