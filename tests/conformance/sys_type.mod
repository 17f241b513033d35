MODULE sys_type
    ! Type gives the declared type name of its data argument: an alias its own name
    ! (as declared), \BaseName the type the alias stands for; records, components,
    ! predefined records (pos) and arrays (the element type) by their type names.
    ALIAS num level;
    RECORD mydata
        num a;
        string b;
    ENDRECORD
    VAR level lv := 3;
    VAR mydata d;
    VAR robtarget p;
    VAR errnum e;
    PROC main()
        VAR num arr{3};
        TPWrite Type(lv);
        TPWrite Type(lv \BaseName);
        TPWrite Type(d);
        TPWrite Type(d.b);
        TPWrite Type(p.trans);
        TPWrite Type(arr);
        TPWrite Type(arr{2});
        TPWrite Type(e \BaseName);
        TPWrite Type(e);
    ENDPROC
ENDMODULE
