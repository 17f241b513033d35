MODULE divzero_handled
    ! Division by zero gives ERR_DIVZERO (manual 1.12); TRYNEXT goes on with
    ! the next statement, so the failed assignment leaves x unchanged.
    PROC main()
        VAR num zero := 0;
        VAR num x := 1;
        x := 5 / zero;
        TPWrite "x=" \Num:=x;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "division by zero";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
