MODULE motion_path_store
    ! StorePath/RestoPath (manual: StorePath, RestoPath, PathLevel). Times from the
    ! timing model (docs/semantics.md, motion): IRB 120, TCP acceleration 10 m/s^2,
    ! fine-point settle 0.05 s, so a 100 mm MoveL at v100 to a fine point takes
    ! 100/100 + 100/10000 + 0.05 = 1.06 s.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR clock c;

    PROC main()
        VAR robtarget here;
        MoveJ p0, v1000, fine, tool0;
        TPWrite "level " \Num:=PathLevel();
        ClkStart c;
        MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
        ! At 0.3 s the TCP is 0.5 + 0.29 * 100 = 29.5 mm along.
        WaitTime 0.3;
        StopMove;
        StorePath;
        TPWrite "stored, level " \Num:=PathLevel();
        ! The stop-move state of the stored path stays set on level 2.
        TPWrite "stop-move state " \Bool:=IsStopMoveAct(\FromMoveTask);
        here := CRobT(\Tool:=tool0);
        TPWrite "stopped at x " \Num:=here.trans.x;
        ! Level 2: 50 mm up and back, 0.5 + 0.01 + 0.05 = 0.56 s each: back at 1.42 s.
        MoveL Offs(here, 0, 0, 50), v100, fine, tool0;
        MoveL here, v100, fine, tool0;
        TPWrite "back after " + NumToStr(ClkRead(c), 2);
        RestoPath;
        TPWrite "restored, level " \Num:=PathLevel();
        TPWrite "still stopped " \Bool:=IsStopMoveAct(\FromMoveTask);
        StartMove;
        ! The base path stood 1.42 - 0.3 = 1.12 s: it ends at 1.06 + 1.12 = 2.18 s.
        WaitRob \InPos;
        TPWrite "arrived after " + NumToStr(ClkRead(c), 2);
        here := CRobT(\Tool:=tool0);
        TPWrite "at x " \Num:=here.trans.x;
    ENDPROC
ENDMODULE
