MODULE recover_trynext_loop
    ! TRYNEXT inside a FOR body continues with the rest of the loop.
    PROC main()
        VAR num vals{5} := [1, 0, 2, 0, 4];
        FOR i FROM 1 TO 5 DO
            TPWrite "result " \Num:=100 / vals{i};
        ENDFOR
        TPWrite "done";
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "skip zero";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
