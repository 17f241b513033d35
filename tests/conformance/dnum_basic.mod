MODULE dnum_basic
    ! dnum operators (manual 1.3.1): + - * / DIV MOD and unary minus.
    PROC main()
        VAR dnum d1 := 7;
        VAR dnum d2 := 2;
        TPWrite "add=" \Dnum:=d1 + d2;
        TPWrite "sub=" \Dnum:=d1 - d2;
        TPWrite "mul=" \Dnum:=d1 * d2;
        TPWrite "div=" \Dnum:=d1 / d2;
        TPWrite "idiv=" \Dnum:=d1 DIV d2;
        TPWrite "mod=" \Dnum:=d1 MOD d2;
        TPWrite "neg=" \Dnum:=-d1;
        TPWrite "quarter=" \Dnum:=d2 / 8;
    ENDPROC
ENDMODULE
