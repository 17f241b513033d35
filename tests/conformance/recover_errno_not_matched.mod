MODULE recover_errno_not_matched
    ! A handler that only treats one errno passes others on with RAISE.
    VAR num zero := 0;

    PROC work(num kind)
        VAR num a{1};
        VAR num idx := 2;
        VAR num x;
        IF kind = 1 x := 1 / zero;
        IF kind = 2 x := a{idx};
        TPWrite "work done";
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "work fixed divzero";
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    PROC main()
        work 1;
        work 2;
        work 3;
    ERROR
        IF ERRNO = ERR_OUTOFBND TPWrite "main got outofbnd";
        TRYNEXT;
    ENDPROC
ENDMODULE
