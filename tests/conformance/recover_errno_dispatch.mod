MODULE recover_errno_dispatch
    ! One handler told apart errors by ERRNO with TEST.
    PROC attempt(num kind)
        VAR num a{2};
        VAR num idx := 3;
        VAR num zero := 0;
        VAR num x;
        TEST kind
        CASE 1:
            x := 1 / zero;
        CASE 2:
            x := a{idx};
        CASE 3:
            RAISE 7;
        ENDTEST
        TPWrite "no error";
    ERROR
        TEST ERRNO
        CASE ERR_DIVZERO:
            TPWrite "divzero";
        CASE ERR_OUTOFBND:
            TPWrite "outofbnd";
        CASE 7:
            TPWrite "user 7";
        DEFAULT:
            TPWrite "other";
        ENDTEST
        RETURN;
    ENDPROC

    PROC main()
        FOR k FROM 1 TO 4 DO
            attempt k;
        ENDFOR
    ENDPROC
ENDMODULE
