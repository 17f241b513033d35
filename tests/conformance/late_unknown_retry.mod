MODULE late_unknown_retry
    ! The handler corrects the name and RETRY evaluates the late-bound call
    ! again (manual 1.12).
    PROC good()
        TPWrite "good called";
    ENDPROC

    PROC main()
        VAR string name := "bad";
        % name %;
        TPWrite "name=" + name;
    ERROR
        IF ERRNO = ERR_REFUNKPRC THEN
            TPWrite "fixing " + name;
            name := "good";
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
