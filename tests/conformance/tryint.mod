MODULE tryint
    ! TryInt accepts integers within the exact-integer range of their type (num up to
    ! 8388608, dnum up to 4503599627370496); a fraction raises ERR_INT_NOTVAL, a
    ! too-large integer ERR_INT_MAXVAL.
    VAR num stage := 0;

    PROC main()
        VAR num whole := 42;
        VAR num half := 2.5;
        VAR num big := 16777216;
        VAR dnum dbig := 4503599627370496;
        TryInt whole;
        TryInt dbig;
        TPWrite "integers pass";
        stage := 1;
        TryInt half;
        stage := 2;
        TryInt big;
        TPWrite "end";
    ERROR
        IF ERRNO = ERR_INT_NOTVAL TPWrite "stage " \Num:=stage;
        IF ERRNO = ERR_INT_NOTVAL TPWrite "not an integer";
        IF ERRNO = ERR_INT_MAXVAL TPWrite "too large";
        TRYNEXT;
    ENDPROC
ENDMODULE
