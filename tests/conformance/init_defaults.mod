MODULE init_defaults
    ! Uninitialised data: num 0, string empty, bool FALSE (manual 1.2.2),
    ! for module data, routine data and array elements.
    VAR num gn;
    VAR string gs;
    VAR bool gb;
    VAR num garr{3};

    PROC main()
        VAR num n;
        VAR string s;
        VAR bool b;
        VAR dnum d;
        VAR pos p;
        TPWrite "gn=" \Num:=gn;
        TPWrite "gs=[" + gs + "]";
        TPWrite "gb=" \Bool:=gb;
        TPWrite "garr3=" \Num:=garr{3};
        TPWrite "n=" \Num:=n;
        TPWrite "s=[" + s + "]";
        TPWrite "b=" \Bool:=b;
        TPWrite "d=" \Dnum:=d;
        TPWrite "p.x+p.y+p.z=" \Num:=p.x + p.y + p.z;
    ENDPROC
ENDMODULE
