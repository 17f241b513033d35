MODULE matrix_errors
    ! Error paths of the matrix instructions, each handled by name. The errnos are the
    ! choices documented in crates/rapid-vm/src/builtins/matrix/mod.rs (uncertain):
    ! ERR_ARRAY_SIZE for a bad \A_m/\A_n or a shape A may not have, ERR_INVDIM when
    ! operands do not fit each other, ERR_NOTEQDIM for a result array that is too small,
    ! ERR_CALC_DIVZERO for a singular matrix.
    PROC report(string what)
        IF ERRNO = ERR_ARRAY_SIZE THEN
            TPWrite what + ": ERR_ARRAY_SIZE";
        ELSEIF ERRNO = ERR_INVDIM THEN
            TPWrite what + ": ERR_INVDIM";
        ELSEIF ERRNO = ERR_NOTEQDIM THEN
            TPWrite what + ": ERR_NOTEQDIM";
        ELSEIF ERRNO = ERR_CALC_DIVZERO THEN
            TPWrite what + ": ERR_CALC_DIVZERO";
        ELSE
            TPWrite what + ": another error";
        ENDIF
    ENDPROC

    PROC add_shapes()
        VAR dnum a{2, 3};
        VAR dnum b{2, 2};
        VAR dnum c{2, 3};
        MatrixAdd a, b, c;
        TPWrite "add shapes: no error";
    ERROR
        report "add shapes";
        RETURN;
    ENDPROC

    PROC mult_shapes()
        VAR dnum a{2, 3};
        VAR dnum b{2, 2};
        VAR dnum c{2, 2};
        MatrixMult a, b, c;
        TPWrite "mult shapes: no error";
    ERROR
        report "mult shapes";
        RETURN;
    ENDPROC

    PROC result_small()
        VAR dnum a{2, 3};
        VAR dnum n{3, 2};
        VAR dnum c{1, 2};
        MatrixMult a, n, c;
        TPWrite "result small: no error";
    ERROR
        report "result small";
        RETURN;
    ENDPROC

    PROC rows_too_many()
        VAR dnum a{2, 2};
        VAR dnum c{3, 3};
        MatrixTranspose a \A_m:=3, c;
        TPWrite "rows too many: no error";
    ERROR
        report "rows too many";
        RETURN;
    ENDPROC

    PROC cols_fraction()
        VAR dnum a{2, 2};
        MatrixReset a \A_n:=1.5;
        TPWrite "cols fraction: no error";
    ERROR
        report "cols fraction";
        RETURN;
    ENDPROC

    PROC inverse_singular()
        VAR dnum a{2, 2} := [[1, 2], [2, 4]];
        VAR dnum inv{2, 2};
        MatrixInverse a, inv;
        TPWrite "inverse singular: no error";
    ERROR
        report "inverse singular";
        RETURN;
    ENDPROC

    PROC inverse_not_square()
        VAR dnum a{2, 3};
        VAR dnum inv{3, 3};
        MatrixInverse a, inv;
        TPWrite "inverse not square: no error";
    ERROR
        report "inverse not square";
        RETURN;
    ENDPROC

    PROC solve_wide()
        VAR dnum a{2, 3} := [[1, 0, 0], [0, 1, 0]];
        VAR dnum b{2};
        VAR dnum x{3};
        MatrixSolve a, b, x;
        TPWrite "solve wide: no error";
    ERROR
        report "solve wide";
        RETURN;
    ENDPROC

    PROC solve_short_b()
        VAR dnum a{3, 3} := [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
        VAR dnum b{2};
        VAR dnum x{3};
        MatrixSolve a, b, x;
        TPWrite "solve short b: no error";
    ERROR
        report "solve short b";
        RETURN;
    ENDPROC

    PROC solve_singular()
        ! Rank 1: the second column is twice the first.
        VAR dnum a{3, 2} := [[1, 2], [2, 4], [3, 6]];
        VAR dnum b{3} := [1, 2, 3];
        VAR dnum x{2};
        MatrixSolve a, b, x;
        TPWrite "solve singular: no error";
    ERROR
        report "solve singular";
        RETURN;
    ENDPROC

    PROC block_ok()
        ! A 3x3 array used as the 2x2 block [[2,0],[0,4]]: invertible although the
        ! whole array is singular (its last row is zero).
        VAR dnum a{3, 3} := [[2, 0, 9], [0, 4, 9], [0, 0, 0]];
        VAR dnum inv{2, 2};
        MatrixInverse a \A_n:=2, inv;
        TPWrite "block inverse: " + DnumToStr(inv{1, 1}, 2) + " " + DnumToStr(inv{2, 2}, 2);
    ERROR
        report "block inverse";
        RETURN;
    ENDPROC

    PROC main()
        add_shapes;
        mult_shapes;
        result_small;
        rows_too_many;
        cols_fraction;
        inverse_singular;
        inverse_not_square;
        solve_wide;
        solve_short_b;
        solve_singular;
        block_ok;
    ENDPROC
ENDMODULE
