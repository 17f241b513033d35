MODULE motion_path_recorder
    ! The path recorder (manual: PathRecStart, PathRecMoveBwd, PathRecMoveFwd,
    ! PathRecValidBwd, PathRecValidFwd, PathRecStop). Times from the timing model
    ! (docs/semantics.md, motion): TCP acceleration 10 m/s^2, fine-point settle
    ! 0.05 s, so a stop-to-stop MoveL of L mm at v100 takes L/100 + 0.01 + 0.05 s.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR pathrecid start_id;
    VAR pathrecid corner_id;
    VAR clock c;

    PROC main()
        VAR pos at;
        MoveJ p0, v1000, fine, tool0;
        TPWrite "before recording " \Bool:=PathRecValidBwd();
        PathRecStart start_id;
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        PathRecStart corner_id;
        MoveL Offs(p0, 100, 100, 0), v100, fine, tool0;
        MoveL \Conc, Offs(p0, 0, 100, 0), v100, fine, tool0;
        ! Stopped 0.3 s into the third leg: 29.5 mm along it, at x = 370.5.
        WaitTime 0.3;
        StopMove;
        StorePath;
        TPWrite "valid back " \Bool:=PathRecValidBwd();
        TPWrite "valid back to the corner " \Bool:=PathRecValidBwd(\ID:=corner_id);
        TPWrite "valid forward " \Bool:=PathRecValidFwd();
        ClkStart c;
        ! Back along the third leg (29.5 mm: 0.295 + 0.01 + 0.05 s, a stop point as
        ! programmed there) and the second (1.06 s) to the corner mark: 1.415 s.
        PathRecMoveBwd \ID:=corner_id;
        at := CPos(\Tool:=tool0);
        TPWrite "back at " + NumToStr(ClkRead(c), 3) \Pos:=at;
        TPWrite "valid forward " \Bool:=PathRecValidFwd();
        TPWrite "valid back to the corner " \Bool:=PathRecValidBwd(\ID:=corner_id);
        TPWrite "valid back " \Bool:=PathRecValidBwd();
        ! On back along the first leg to where recording began (1.06 s): 2.475 s.
        PathRecMoveBwd;
        at := CPos(\Tool:=tool0);
        TPWrite "at the start at " + NumToStr(ClkRead(c), 3) \Pos:=at;
        ! Forward only to the corner mark (1.06 s): 3.535 s.
        PathRecMoveFwd \ID:=corner_id;
        at := CPos(\Tool:=tool0);
        TPWrite "at the corner at " + NumToStr(ClkRead(c), 3) \Pos:=at;
        ! And on to where the robot stopped (1.06 + 0.355 s): 4.95 s.
        PathRecMoveFwd;
        at := CPos(\Tool:=tool0);
        TPWrite "forward at " + NumToStr(ClkRead(c), 3) \Pos:=at;
        TPWrite "valid forward " \Bool:=PathRecValidFwd();
        RestoPath;
        StartMove;
        ! The rest of the third leg: 1.06 - 0.3 = 0.76 s more, 5.71 s.
        WaitRob \InPos;
        TPWrite "done at " + NumToStr(ClkRead(c), 3);
        PathRecStop \Clear;
        TPWrite "after PathRecStop " \Bool:=PathRecValidBwd();
        clearance;
    ENDPROC

    PROC clearance()
        VAR pos at;
        MoveL p0, v1000, fine, tool0;
        PathRecStart start_id;
        MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
        WaitTime 0.3;
        StopMove;
        StorePath;
        ClkReset c;
        ClkStart c;
        ! \ToolOffs [0, 0, 10]: 10 mm of clearance (tool0's z points down, so up):
        ! first 10 mm up (0.1 + 0.01 + 0.05 = 0.16 s), then back along the leg 10 mm
        ! above it (29.5 mm: 0.355 s), 0.515 s.
        PathRecMoveBwd \ToolOffs:=[0, 0, 10];
        at := CPos(\Tool:=tool0);
        TPWrite "back with clearance at " + NumToStr(ClkRead(c), 3) \Pos:=at;
        ! Forward above the leg (0.355 s), then down onto the path (0.16 s): 1.03 s.
        PathRecMoveFwd \ToolOffs:=[0, 0, 10] \Speed:=v100;
        at := CPos(\Tool:=tool0);
        TPWrite "forward with clearance at " + NumToStr(ClkRead(c), 3) \Pos:=at;
        RestoPath;
        StartMove;
        WaitRob \InPos;
        PathRecStop;
    ENDPROC
ENDMODULE
