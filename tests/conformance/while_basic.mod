MODULE while_basic
    ! WHILE repeats while its condition is TRUE (manual 1.4 example).
    PROC main()
        VAR num index := 3;
        WHILE index > 0 DO
            TPWrite "count " \Num:=index;
            index := index - 1;
        ENDWHILE
        TPWrite "liftoff";
        WHILE FALSE DO
            TPWrite "never";
        ENDWHILE
        TPWrite "index=" \Num:=index;
    ENDPROC
ENDMODULE
