MODULE arr_outofbnd_2d
    ! Each index is checked against its own dimension.
    PROC main()
        VAR num m{3, 4};
        VAR num i := 2;
        VAR num j := 5;
        m{i, j} := 1;
        i := 4;
        j := 1;
        m{i, j} := 2;
        i := 3;
        j := 4;
        m{i, j} := 3;
        TPWrite "m34=" \Num:=m{3, 4};
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            TPWrite "out of bounds " + ValToStr(i) + "," + ValToStr(j);
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
