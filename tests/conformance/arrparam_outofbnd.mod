MODULE arrparam_outofbnd
    ! Bounds of an open array parameter are those of the argument; going past
    ! them raises ERR_OUTOFBND, here caught by the caller's handler.
    FUNC num sumFirst(num a{*}, num n)
        VAR num s := 0;
        FOR i FROM 1 TO n DO
            s := s + a{i};
        ENDFOR
        RETURN s;
    ENDFUNC

    PROC main()
        VAR num three{3} := [1, 2, 3];
        VAR num r := -1;
        r := sumFirst(three, 3);
        TPWrite "r=" \Num:=r;
        r := sumFirst(three, 4);
        TPWrite "r=" \Num:=r;
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            TPWrite "past the end";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
