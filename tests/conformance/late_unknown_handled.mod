MODULE late_unknown_handled
    ! A late-bound call to an unknown procedure sets ERRNO to ERR_REFUNKPRC
    ! (manual 1.1.5), which an ERROR handler can catch.
    PROC main()
        VAR string name := "no_such_proc";
        TPWrite "calling";
        % name %;
        TPWrite "continued";
    ERROR
        IF ERRNO = ERR_REFUNKPRC THEN
            TPWrite "unknown procedure";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
