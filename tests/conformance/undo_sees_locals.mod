MODULE undo_sees_locals
    ! An UNDO handler can read the routine's local data (manual 1.13,
    ! restrictions: all variables reachable from the body).
    PROC work()
        VAR num stage := 0;
        stage := 1;
        stage := 2;
        TPWrite "working";
        EXIT;
        stage := 3;
    UNDO
        TPWrite "undo at stage " \Num:=stage;
    ENDPROC

    PROC main()
        work;
    ENDPROC
ENDMODULE
