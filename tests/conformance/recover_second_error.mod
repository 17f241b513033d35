MODULE recover_second_error
    ! The handler runs again for a later error in the same routine; ERRNO
    ! holds the latest error each time.
    PROC main()
        VAR num zero := 0;
        VAR num a{2};
        VAR num idx := 3;
        VAR num x;
        x := 1 / zero;
        TPWrite "between";
        x := a{idx};
        TPWrite "end";
    ERROR
        IF ERRNO = ERR_DIVZERO TPWrite "first: divzero";
        IF ERRNO = ERR_OUTOFBND TPWrite "second: outofbnd";
        TRYNEXT;
    ENDPROC
ENDMODULE
