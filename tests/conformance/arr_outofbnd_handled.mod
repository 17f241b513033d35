MODULE arr_outofbnd_handled
    ! An index outside the declared size raises ERR_OUTOFBND (semantics 1.3);
    ! index 0 is outside too, since arrays start at 1.
    PROC main()
        VAR num a{5};
        VAR num idx := 6;
        VAR num x := -1;
        VAR num caught := 0;
        a{idx} := 1;
        idx := 0;
        x := a{idx};
        TPWrite "x=" \Num:=x;
        idx := 5;
        a{idx} := 55;
        TPWrite "a5=" \Num:=a{5};
        TPWrite "caught=" \Num:=caught;
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            TPWrite "index out of bounds";
            caught := caught + 1;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
