MODULE arr_3d
    ! Three-dimensional array filled in row-major order.
    PROC main()
        VAR num c{2, 3, 4};
        VAR num k := 0;
        VAR num sum := 0;
        FOR i FROM 1 TO 2 DO
            FOR j FROM 1 TO 3 DO
                FOR l FROM 1 TO 4 DO
                    k := k + 1;
                    c{i, j, l} := k;
                ENDFOR
            ENDFOR
        ENDFOR
        TPWrite "c111=" \Num:=c{1, 1, 1};
        TPWrite "c121=" \Num:=c{1, 2, 1};
        TPWrite "c213=" \Num:=c{2, 1, 3};
        TPWrite "c234=" \Num:=c{2, 3, 4};
        TPWrite "dims=" \Num:=Dim(c, 1) * 100 + Dim(c, 2) * 10 + Dim(c, 3);
        FOR i FROM 1 TO 2 DO
            FOR j FROM 1 TO 3 DO
                FOR l FROM 1 TO 4 DO
                    sum := sum + c{i, j, l};
                ENDFOR
            ENDFOR
        ENDFOR
        TPWrite "sum=" \Num:=sum;
    ENDPROC
ENDMODULE
