MODULE matrix_decomp
    ! MatrixInverse, MatrixSolve (square and least squares), MatrixSolveQR and MatrixSVD
    ! on matrices worked out by hand. Values are printed with DnumToStr to a few decimals,
    ! so rounding noise in the last bits of a dnum does not show. Signs of singular
    ! vectors are not unique, so the SVD is checked through U diag(S) V^T = A and
    ! U^T U = I, V^T V = I; the QR through its unique form (diagonal of R >= 0).
    PROC show(string name, dnum m{*,*})
        VAR string row;
        FOR i FROM 1 TO Dim(m, 1) DO
            row := name + " row" + NumToStr(i, 0) + ":";
            FOR j FROM 1 TO Dim(m, 2) DO
                row := row + " " + DnumToStr(m{i, j}, 3);
            ENDFOR
            TPWrite row;
        ENDFOR
    ENDPROC

    PROC showvec(string name, dnum v{*})
        VAR string row;
        row := name + ":";
        FOR i FROM 1 TO Dim(v, 1) DO
            row := row + " " + DnumToStr(v{i}, 3);
        ENDFOR
        TPWrite row;
    ENDPROC

    ! Largest |(X^T X - I){i,j}|, printed rounded: 0.000 when X has orthonormal columns.
    PROC orthonormal(string name, dnum x{*,*})
        VAR dnum worst := 0;
        VAR dnum s;
        FOR i FROM 1 TO Dim(x, 2) DO
            FOR j FROM 1 TO Dim(x, 2) DO
                s := 0;
                FOR k FROM 1 TO Dim(x, 1) DO
                    s := s + x{k, i} * x{k, j};
                ENDFOR
                IF i = j s := s - 1;
                IF Abs(DnumToNum(s)) > DnumToNum(worst) worst := Abs(DnumToNum(s));
            ENDFOR
        ENDFOR
        TPWrite name + " orthonormal error: " + DnumToStr(worst, 3);
    ENDPROC

    PROC main()
        VAR dnum a2{2, 2} := [[4, 7], [2, 6]];
        VAR dnum inv2{2, 2};
        VAR dnum a3{3, 3} := [[1, 2, 3], [0, 1, 4], [5, 6, 0]];
        VAR dnum inv3{3, 3};
        VAR dnum b3{3} := [14, 14, 17];
        VAR dnum x3{3};
        VAR dnum line{3, 2} := [[1, 0], [1, 1], [1, 2]];
        VAR dnum y{3} := [1, 3, 2];
        VAR dnum coef{2};
        VAR dnum qa{2, 2} := [[3, 1], [4, 2]];
        VAR dnum q2{2, 2};
        VAR dnum r2{2, 2};
        VAR dnum tall{3, 2} := [[3, 0], [4, 0], [0, 2]];
        VAR dnum q3{3, 3};
        VAR dnum r3{3, 2};
        VAR dnum q3abs{3, 3};
        VAR dnum sa{2, 3} := [[3, 2, 2], [2, 3, -2]];
        VAR dnum u{2, 2};
        VAR dnum s{2};
        VAR dnum v{3, 3};
        VAR dnum usv{2, 3};
        VAR dnum st{3, 2} := [[3, 2], [2, 3], [2, -2]];
        VAR dnum ue{3, 2};
        VAR dnum uf{3, 3};
        VAR dnum v2{2, 2};

        ! [[4,7],[2,6]]: det 10, inverse [[6,-7],[-2,4]] / 10.
        MatrixInverse a2, inv2;
        show "inv2", inv2;
        ! det 1: the inverse is [[-24,18,5],[20,-15,-4],[-5,4,1]].
        MatrixInverse a3, inv3;
        show "inv3", inv3;
        ! b3 = a3 * [1,2,3].
        MatrixSolve a3, b3, x3;
        showvec "x3", x3;
        ! Least squares line through (0,1) (1,3) (2,2): normal equations
        ! [[3,3],[3,5]] c = [6,7], so c = [1.5, 0.5].
        MatrixSolve line, y, coef;
        showvec "line", coef;
        ! Gram-Schmidt by hand: q1 = (0.6,0.8), r11 = 5, r12 = 2.2,
        ! q2 = (-0.8,0.6), r22 = 0.4.
        MatrixSolveQR qa, q2, r2;
        show "q2", q2;
        show "r2", r2;
        ! Tall: q1 = (0.6,0.8,0), q2 = (0,0,1), R = [[5,0],[0,2],[0,0]]; the third
        ! column of Q is (0.8,-0.6,0) up to its sign, so it is printed as |Q|.
        MatrixSolveQR tall, q3, r3;
        FOR i FROM 1 TO 3 DO
            FOR j FROM 1 TO 3 DO
                q3abs{i, j} := AbsDnum(q3{i, j});
            ENDFOR
        ENDFOR
        show "q3 abs", q3abs;
        show "r3", r3;
        orthonormal "q3", q3;
        ! [[3,2,2],[2,3,-2]]: A A^T = [[17,8],[8,17]], eigenvalues 25 and 9.
        MatrixSVD sa, u, s, v;
        showvec "s", s;
        FOR i FROM 1 TO 2 DO
            FOR j FROM 1 TO 3 DO
                usv{i, j} := u{i, 1} * s{1} * v{j, 1} + u{i, 2} * s{2} * v{j, 2};
            ENDFOR
        ENDFOR
        show "usv", usv;
        orthonormal "u", u;
        orthonormal "v", v;
        ! The transpose has the same singular values; \Econ gives U as 3x2.
        MatrixSVD st, ue, s, v2 \Econ;
        showvec "s econ", s;
        orthonormal "u econ", ue;
        MatrixSVD st, uf, s, v2;
        orthonormal "u full", uf;
        orthonormal "v2", v2;
    ENDPROC
ENDMODULE
