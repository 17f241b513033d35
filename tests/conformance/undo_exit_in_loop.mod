MODULE undo_exit_in_loop
    ! EXIT inside a loop; the UNDO handler reports the module data.
    VAR num done := 0;

    PROC main()
        FOR i FROM 1 TO 5 DO
            done := done + 1;
            IF i = 2 EXIT;
        ENDFOR
        TPWrite "not reached";
    UNDO
        TPWrite "undo after " \Num:=done;
    ENDPROC
ENDMODULE
