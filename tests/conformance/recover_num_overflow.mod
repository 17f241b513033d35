MODULE recover_num_overflow
    ! A num product beyond IEEE single range is an error (docs/semantics.md O1),
    ! caught here by an ERROR handler.
    PROC main()
        VAR num big := 1E38;
        VAR num x;
        x := big * 10;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_NUM_LIMIT THEN
            TPWrite "overflow caught";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
