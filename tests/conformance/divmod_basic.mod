MODULE divmod_basic
    ! Integer division and modulo (manual 1.3.1 note iii: 14 DIV 4=3, 14 MOD 4=2).
    PROC main()
        TPWrite "a=" \Num:=14 DIV 4;
        TPWrite "b=" \Num:=14 MOD 4;
        TPWrite "c=" \Num:=12 DIV 3;
        TPWrite "d=" \Num:=12 MOD 3;
        TPWrite "e=" \Num:=3 DIV 5;
        TPWrite "f=" \Num:=3 MOD 5;
        TPWrite "g=" \Num:=0 DIV 7;
        TPWrite "h=" \Num:=100 DIV 7;
        TPWrite "i=" \Num:=100 MOD 7;
    ENDPROC
ENDMODULE
