MODULE motion_path_store_two_traps
    ! One trap stops the robot and sets its path aside (StopMove, StorePath, a move on
    ! path level 2); a later trap takes it back (a move back, RestoPath, StartMove). In
    ! between the routine stays in the move it waits for (§2.3: the instruction after a
    ! stop point runs when the robot stands at the point). Times as in
    ! motion_path_store: the 100 mm MoveL at v100 takes 1.06 s; the first trap comes at
    ! 0.3 s, its 50 mm move up takes 0.56 s; the second at 2.0 s, 0.56 s down again, so
    ! the base path stands from 0.3 to 2.56 s (2.26 s) and the move ends at 3.32 s.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR clock c;
    VAR intnum aside_int;
    VAR intnum back_int;

    TRAP step_aside
        VAR robtarget here;
        StopMove;
        StorePath;
        here := CRobT(\Tool:=tool0);
        MoveL Offs(here, 0, 0, 50), v100, fine, tool0;
        TPWrite "aside after " + NumToStr(ClkRead(c), 2);
    ENDTRAP

    TRAP step_back
        VAR robtarget here;
        here := CRobT(\Tool:=tool0);
        MoveL Offs(here, 0, 0, -50), v100, fine, tool0;
        RestoPath;
        StartMove;
        TPWrite "back after " + NumToStr(ClkRead(c), 2);
    ENDTRAP

    PROC main()
        VAR robtarget here;
        MoveJ p0, v1000, fine, tool0;
        CONNECT aside_int WITH step_aside;
        CONNECT back_int WITH step_back;
        ITimer \Single, 0.3, aside_int;
        ITimer \Single, 2.0, back_int;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        TPWrite "arrived after " + NumToStr(ClkRead(c), 2);
        here := CRobT(\Tool:=tool0);
        TPWrite "at x " \Num:=here.trans.x;
    ENDPROC
ENDMODULE
