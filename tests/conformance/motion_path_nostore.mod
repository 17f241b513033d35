MODULE motion_path_nostore
    ! RestoPath needs a path StorePath stored (manual: RestoPath); without one the
    ! program stops (no recoverable error is documented for it).
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        TPWrite "level " \Num:=PathLevel();
        RestoPath;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
