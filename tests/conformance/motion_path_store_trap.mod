MODULE motion_path_store_trap
    ! A trap stops the robot during the move the main routine waits for, sets its path
    ! aside, moves on path level 2 and restarts the path (StopMove, StorePath, RestoPath,
    ! StartMove): the move instruction ends when the robot reaches its point, not before.
    ! Times from the timing model as in motion_path_store: the 100 mm MoveL at v100 takes
    ! 100/100 + 100/10000 + 0.05 = 1.06 s; the trap comes at 0.3 s, its two 50 mm moves
    ! take 0.56 s each, so the base path stands 1.12 s and the move ends at 2.18 s.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR clock c;
    VAR intnum pause_int;

    TRAP pause_path
        VAR robtarget here;
        StopMove;
        StorePath;
        here := CRobT(\Tool:=tool0);
        MoveL Offs(here, 0, 0, 50), v100, fine, tool0;
        MoveL here, v100, fine, tool0;
        TPWrite "back on the path after " + NumToStr(ClkRead(c), 2);
        RestoPath;
        StartMove;
    ENDTRAP

    PROC main()
        VAR robtarget here;
        MoveJ p0, v1000, fine, tool0;
        CONNECT pause_int WITH pause_path;
        ITimer \Single, 0.3, pause_int;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        TPWrite "arrived after " + NumToStr(ClkRead(c), 2);
        here := CRobT(\Tool:=tool0);
        TPWrite "at x " \Num:=here.trans.x;
    ENDPROC
ENDMODULE
