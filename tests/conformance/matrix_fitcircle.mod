MODULE matrix_fitcircle
    ! FitCircle on points worked out by hand. The normal points so that the points run
    ! counter-clockwise about it in the order given (choice documented in
    ! crates/rapid-vm/src/builtins/matrix/fit.rs). Results are rounded before printing.
    PROC showfit(string name, pos c, num r, pos n)
        TPWrite name + " center=[" + NumToStr(c.x, 3) + "," + NumToStr(c.y, 3) + "," + NumToStr(c.z, 3) + "] radius=" + NumToStr(r, 3);
        TPWrite name + " normal=[" + NumToStr(n.x, 3) + "," + NumToStr(n.y, 3) + "," + NumToStr(n.z, 3) + "]";
    ENDPROC

    PROC collinear()
        VAR dnum pts{3, 3} := [[0, 0, 0], [1, 1, 1], [2, 2, 2]];
        VAR pos c;
        VAR num r;
        VAR pos n;
        FitCircle pts, c, r, n;
        TPWrite "collinear: no error";
    ERROR
        IF ERRNO = ERR_CALC_DIVZERO TPWrite "collinear: ERR_CALC_DIVZERO";
        RETURN;
    ENDPROC

    PROC two_columns()
        VAR dnum pts{4, 2};
        VAR pos c;
        VAR num r;
        VAR pos n;
        FitCircle pts, c, r, n;
        TPWrite "two columns: no error";
    ERROR
        IF ERRNO = ERR_INVDIM TPWrite "two columns: ERR_INVDIM";
        RETURN;
    ENDPROC

    PROC too_few()
        VAR dnum pts{4, 3} := [[6, 2, 3], [1, 7, 3], [-4, 2, 3], [1, -3, 3]];
        VAR pos c;
        VAR num r;
        VAR pos n;
        FitCircle pts \NumPoints:=2, c, r, n;
        TPWrite "too few: no error";
    ERROR
        IF ERRNO = ERR_ARRAY_SIZE TPWrite "too few: ERR_ARRAY_SIZE";
        RETURN;
    ENDPROC

    PROC main()
        ! Radius 5 about (1,2,3) in the plane z = 3, counter-clockwise seen from +z.
        VAR dnum pts{4, 3} := [[6, 2, 3], [1, 7, 3], [-4, 2, 3], [1, -3, 3]];
        ! The same circle run the other way: the normal flips.
        VAR dnum back{3, 3} := [[1, -3, 3], [-4, 2, 3], [1, 7, 3]];
        ! Radius 5 about the origin, alternately 1 above and 1 below the plane z = 0:
        ! the best plane is z = 0 and every point misses the circle by exactly 1.
        VAR dnum wavy{4, 3} := [[5, 0, 1], [0, 5, -1], [-5, 0, 1], [0, -5, -1]];
        VAR pos c;
        VAR num r;
        VAR pos n;
        VAR num rms;
        VAR num maxerr;
        VAR num worst;

        FitCircle pts, c, r, n \RMS:=rms \MaxErr:=maxerr \IndexWorst:=worst;
        showfit "exact", c, r, n;
        TPWrite "exact rms=" + NumToStr(rms, 3) + " maxerr=" + NumToStr(maxerr, 3);
        ! Only the first three points: the same circle.
        FitCircle pts \NumPoints:=3, c, r, n;
        showfit "three", c, r, n;
        FitCircle back, c, r, n;
        showfit "back", c, r, n;
        FitCircle wavy, c, r, n \RMS:=rms \MaxErr:=maxerr \IndexWorst:=worst;
        showfit "wavy", c, r, n;
        TPWrite "wavy rms=" + NumToStr(rms, 3) + " maxerr=" + NumToStr(maxerr, 3) + " worst=" + NumToStr(worst, 0);
        collinear;
        two_columns;
        too_few;
    ENDPROC
ENDMODULE
