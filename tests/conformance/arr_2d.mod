MODULE arr_2d
    ! Two-dimensional arrays: element m{i,j}, Dim per dimension.
    PROC main()
        VAR num m{3, 4};
        VAR num g{2, 3} := [[1, 2, 3], [4, 5, 6]];
        VAR num rowsum := 0;
        FOR i FROM 1 TO 3 DO
            FOR j FROM 1 TO 4 DO
                m{i, j} := i * 10 + j;
            ENDFOR
        ENDFOR
        TPWrite "m23=" \Num:=m{2, 3};
        TPWrite "m34=" \Num:=m{3, 4};
        TPWrite "dim1=" \Num:=Dim(m, 1);
        TPWrite "dim2=" \Num:=Dim(m, 2);
        FOR j FROM 1 TO 4 DO
            rowsum := rowsum + m{2, j};
        ENDFOR
        TPWrite "row2=" \Num:=rowsum;
        TPWrite "g21=" \Num:=g{2, 1};
        TPWrite "g13=" \Num:=g{1, 3};
    ENDPROC
ENDMODULE
