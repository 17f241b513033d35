MODULE matrix_basic
    ! MatrixAdd, MatrixSub, MatrixMult (matrix and scalar), MatrixTranspose, MatrixReset
    ! on small integer matrices worked out by hand; \A_m/\A_n select the top-left block
    ! and a larger result array keeps its other elements (uncertain, see matrix/mod.rs).
    PROC show(string name, dnum m{*,*})
        VAR string row;
        FOR i FROM 1 TO Dim(m, 1) DO
            row := name + " row" + NumToStr(i, 0) + ":";
            FOR j FROM 1 TO Dim(m, 2) DO
                row := row + " " + DnumToStr(m{i, j}, 2);
            ENDFOR
            TPWrite row;
        ENDFOR
    ENDPROC

    PROC main()
        VAR dnum a{2, 2} := [[1, 2], [3, 4]];
        VAR dnum b{2, 2} := [[5, 6], [7, 8]];
        VAR dnum c{2, 2};
        VAR dnum m{2, 3} := [[1, 2, 3], [4, 5, 6]];
        VAR dnum n{3, 2} := [[1, 0], [0, 1], [1, 1]];
        VAR dnum mt{3, 2};
        VAR dnum big{3, 3} := [[1, 2, 3], [4, 5, 6], [7, 8, 9]];
        VAR dnum c3{3, 3} := [[-1, -1, -1], [-1, -1, -1], [-1, -1, -1]];
        VAR dnum k := 2.5;

        MatrixAdd a, b, c;
        show "add", c;
        MatrixSub a, b, c;
        show "sub", c;
        MatrixMult a, b, c;
        show "mult", c;
        MatrixMult a, k, c;
        show "scale", c;
        MatrixTranspose a, c;
        show "transpose", c;
        ! (2x3) * (3x2) = [[1+0+3, 0+2+3], [4+0+6, 0+5+6]]
        MatrixMult m, n, c;
        show "rect", c;
        MatrixTranspose m, mt;
        show "mt", mt;
        ! The top-left 2x2 block of big plus b: [[1+5, 2+6], [4+7, 5+8]].
        MatrixAdd big \A_m:=2 \A_n:=2, b, c3;
        show "block", c3;
        ! Only the first two rows of big are cleared.
        MatrixReset big \A_m:=2;
        show "reset", big;
    ENDPROC
ENDMODULE
