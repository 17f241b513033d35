MODULE arr_init_aggregate
    ! Array declarations with aggregates from manual 1.2.2.
    VAR num maxno{10} := [1, 2, 3, 9, 8, 7, 6, 5, 4, 3];
    CONST pos seq{3} := [[614, 778, 1020], [914, 998, 1021], [814, 998, 1022]];

    PROC main()
        TPWrite "maxno4=" \Num:=maxno{4};
        TPWrite "maxno10=" \Num:=maxno{10};
        TPWrite "seq1x=" \Num:=seq{1}.x;
        TPWrite "seq2y=" \Num:=seq{2}.y;
        TPWrite "seq3z=" \Num:=seq{3}.z;
        maxno := [0, 0, 0, 0, 0, 0, 0, 0, 0, 42];
        TPWrite "maxno1=" \Num:=maxno{1};
        TPWrite "maxno10=" \Num:=maxno{10};
    ENDPROC
ENDMODULE
