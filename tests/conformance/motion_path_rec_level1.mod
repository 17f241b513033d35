MODULE motion_path_rec_level1
    ! The path recorder moves the robot on path level 2, after StorePath (the
    ! manual's examples); on the base path PathRecMoveBwd stops the program.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR pathrecid start_id;

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        PathRecStart start_id;
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        TPWrite "valid " \Bool:=PathRecValidBwd(\ID:=start_id);
        PathRecMoveBwd \ID:=start_id;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
