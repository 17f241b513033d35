MODULE num_precedence
    ! Operator priority (manual 1.3.5): * / DIV MOD before + -, equal
    ! priority is evaluated left to right.
    PROC main()
        TPWrite "a=" \Num:=2 + 3 * 4;
        TPWrite "b=" \Num:=(2 + 3) * 4;
        ! left to right: (10 - 4) - 3
        TPWrite "c=" \Num:=10 - 4 - 3;
        ! left to right: (20 / 4) / 5
        TPWrite "d=" \Num:=20 / 4 / 5;
        TPWrite "e=" \Num:=-2 * 3 + 10;
        TPWrite "f=" \Num:=2 * 3 + 4 * 5;
        ! DIV and * have the same priority: (14 DIV 4) * 2
        TPWrite "g=" \Num:=14 DIV 4 * 2;
        TPWrite "h=" \Num:=2 + 14 MOD 4;
        TPWrite "i=" \Num:=100 - 2 * 3 * 4;
        ! (36 / 6) * 2, not 36 / (6 * 2)
        TPWrite "j=" \Num:=36 / 6 * 2;
    ENDPROC
ENDMODULE
