MODULE recover_raise_escape
    ! RAISE used to leave deeply nested code (manual 1.12: "to escape from
    ! deeply nested code").
    VAR num found_i := 0;
    VAR num found_j := 0;

    PROC search(num target)
        FOR i FROM 1 TO 5 DO
            FOR j FROM 1 TO 5 DO
                IF i * j = target THEN
                    found_i := i;
                    found_j := j;
                    RAISE 1;
                ENDIF
            ENDFOR
        ENDFOR
        TPWrite "not found " \Num:=target;
    ERROR
        IF ERRNO = 1 THEN
            TPWrite "found " + ValToStr(found_i) + "x" + ValToStr(found_j);
            RETURN;
        ENDIF
    ENDPROC

    PROC main()
        search 12;
        search 7;
        search 25;
    ENDPROC
ENDMODULE
