MODULE pers_bool_flag
    ! PERS bool used as a done flag across routines.
    PERS bool done := FALSE;
    PERS num passes := 0;

    PROC work()
        passes := passes + 1;
        IF passes >= 3 done := TRUE;
    ENDPROC

    PROC main()
        WHILE NOT done DO
            work;
        ENDWHILE
        TPWrite "passes=" \Num:=passes;
        TPWrite "done=" \Bool:=done;
    ENDPROC
ENDMODULE
