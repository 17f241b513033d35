MODULE motion_path_twice
    ! One path is stored at a time (manual: StorePath, limitations); a second
    ! StorePath before RestoPath stops the program.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        StorePath;
        TPWrite "level " \Num:=PathLevel();
        StorePath;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
