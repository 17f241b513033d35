MODULE param_multiple_outputs
    ! VAR parameters return several values to the caller (manual 1.1.5).
    PROC divide(num a, num b, VAR num q, VAR num r)
        q := a DIV b;
        r := a MOD b;
    ENDPROC

    PROC minmax(num arr{*}, VAR num lo, VAR num hi)
        lo := arr{1};
        hi := arr{1};
        FOR i FROM 2 TO Dim(arr, 1) DO
            IF arr{i} < lo lo := arr{i};
            IF arr{i} > hi hi := arr{i};
        ENDFOR
    ENDPROC

    PROC main()
        VAR num q;
        VAR num r;
        VAR num data{5} := [7, -2, 9, 4, 0];
        divide 17, 5, q, r;
        TPWrite "q=" \Num:=q;
        TPWrite "r=" \Num:=r;
        minmax data, q, r;
        TPWrite "lo=" \Num:=q;
        TPWrite "hi=" \Num:=r;
    ENDPROC
ENDMODULE
