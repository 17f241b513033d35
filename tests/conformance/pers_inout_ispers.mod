MODULE pers_inout_ispers
    ! An INOUT parameter takes a variable or a whole persistent (manual
    ! 1.1.5); IsPers and IsVar tell which (manual 1.6).
    PERS num p := 10;
    VAR num v := 20;

    PROC bump(INOUT num x)
        x := x + 1;
        TPWrite "pers=" \Bool:=IsPers(x);
        TPWrite "var=" \Bool:=IsVar(x);
    ENDPROC

    PROC main()
        bump p;
        bump v;
        TPWrite "p=" \Num:=p;
        TPWrite "v=" \Num:=v;
    ENDPROC
ENDMODULE
