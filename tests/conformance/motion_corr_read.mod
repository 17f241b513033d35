MODULE motion_corr_read
    ! Path correction bookkeeping, no motion. CorrWrite adds its offset to what its
    ! generator delivered before (corr.rs, uncertain: each write is an increment);
    ! CorrRead returns the sum over the connected generators; CorrDiscon takes one
    ! generator's part away, CorrClear every part (manual: they "remove corrections
    ! given earlier"); a generator connected again starts from nothing.
    VAR corrdescr a;
    VAR corrdescr b;
    PROC main()
        TPWrite "none " \Pos:=CorrRead();
        CorrCon a;
        CorrCon b;
        CorrWrite a, [1, 0, 0];
        CorrWrite a, [0, 2, 0];
        CorrWrite b, [0, 0, 3];
        ! a delivered [1,0,0] + [0,2,0], b [0,0,3].
        TPWrite "both " \Pos:=CorrRead();
        CorrWrite b, [0.5, 0, -1];
        ! b now [0.5,0,2].
        TPWrite "again " \Pos:=CorrRead();
        CorrDiscon b;
        TPWrite "a only " \Pos:=CorrRead();
        CorrCon b;
        TPWrite "b again " \Pos:=CorrRead();
        CorrClear;
        TPWrite "cleared " \Pos:=CorrRead();
        CorrCon a;
        CorrWrite a, [4, 5, 6];
        TPWrite "new " \Pos:=CorrRead();
    ENDPROC
ENDMODULE
