MODULE bwd_all_handlers
    ! A PROC with BACKWARD, ERROR and UNDO handlers, in the order of the
    ! syntax (manual 1.1.5). Forward execution with a handled error runs
    ! only the body and the ERROR handler.
    PROC station(num d)
        VAR num x;
        TPWrite "body";
        x := 10 / d;
        TPWrite "x=" \Num:=x;
    BACKWARD
        TPWrite "backward";
    ERROR
        TPWrite "error handler";
        TRYNEXT;
    UNDO
        TPWrite "undo";
    ENDPROC

    PROC main()
        station 0;
        station 5;
    ENDPROC
ENDMODULE
