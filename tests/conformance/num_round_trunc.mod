MODULE num_round_trunc
    ! Round/Trunc examples of semantics 2.3, plus Abs, Max, Min.
    PROC main()
        TPWrite "r3=" \Num:=Round(0.38521\Dec:=3);
        TPWrite "r1=" \Num:=Round(0.38521\Dec:=1);
        TPWrite "r0=" \Num:=Round(0.38521);
        TPWrite "t3=" \Num:=Trunc(0.38521\Dec:=3);
        TPWrite "t1=" \Num:=Trunc(0.38521\Dec:=1);
        TPWrite "t0=" \Num:=Trunc(0.38521);
        TPWrite "r27=" \Num:=Round(2.7);
        TPWrite "t27=" \Num:=Trunc(2.7);
        ! Trunc cuts towards zero
        TPWrite "tm27=" \Num:=Trunc(-2.7);
        TPWrite "abs1=" \Num:=Abs(-3.5);
        TPWrite "abs2=" \Num:=Abs(4);
        TPWrite "max=" \Num:=Max(3, 7);
        TPWrite "min=" \Num:=Min(3, 7);
        TPWrite "max2=" \Num:=Max(-1, -5);
    ENDPROC
ENDMODULE
