MODULE num_decimals
    ! Decimal results that are exact binary fractions print as short decimals.
    PROC main()
        VAR num x;
        x := 0.5 + 0.25;
        TPWrite "a=" \Num:=x;
        x := 1.5 * 1.5;
        TPWrite "b=" \Num:=x;
        x := 10 / 4;
        TPWrite "c=" \Num:=x;
        x := 1 / 8;
        TPWrite "d=" \Num:=x;
        x := 15 / 4;
        TPWrite "e=" \Num:=x;
        x := 0.75 - 1;
        TPWrite "f=" \Num:=x;
        x := 2.5 * 4;
        TPWrite "g=" \Num:=x;
        x := -0.125 * 8;
        TPWrite "h=" \Num:=x;
    ENDPROC
ENDMODULE
