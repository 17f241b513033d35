MODULE motion_path_errors
    ! StartMove's errors (manual: StartMove, StartMoveRetry, StopMoveReset):
    ! ERR_ALRDY_MOVING when the robot moves and was not stopped, ERR_PATHDIST when
    ! it stands too far from its stopped path (more than 10 mm). Times from the
    ! timing model (docs/semantics.md, motion): a 100 mm MoveL at v100 to a fine
    ! point takes 100/100 + 100/10000 + 0.05 = 1.06 s; stopped 0.3 s into it, the
    ! TCP is 0.5 + 0.29 * 100 = 29.5 mm along.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR clock c;
    VAR robtarget here;

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        already_moving;
        too_far;
        reset;
        retried;
    ENDPROC

    PROC already_moving()
        MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
        StartMove;
        TPWrite "not reached";
        WaitRob \InPos;
    ERROR
        IF ERRNO = ERR_ALRDY_MOVING THEN
            TPWrite "StartMove while moving: ERR_ALRDY_MOVING";
            WaitRob \InPos;
            RETURN;
        ENDIF
    ENDPROC

    PROC too_far()
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
        WaitTime 0.3;
        StopMove;
        StorePath;
        here := CRobT(\Tool:=tool0);
        ! 20 mm up: 0.2 + 0.01 + 0.05 = 0.26 s, at 0.56 s.
        MoveL Offs(here, 0, 0, 20), v100, fine, tool0;
        RestoPath;
        StartMove;
        ! Back 20 mm in the handler (at 0.82 s), then StartMove again: the path
        ! stood 0.52 s, so it ends at 1.06 + 0.52 = 1.58 s.
        WaitRob \InPos;
        TPWrite "arrived after " + NumToStr(ClkRead(c), 2);
    ERROR
        IF ERRNO = ERR_PATHDIST THEN
            TPWrite "20 mm from the path: ERR_PATHDIST, still stopped " \Bool:=IsStopMoveAct(\FromMoveTask);
            StorePath;
            MoveL here, v100, fine, tool0;
            RestoPath;
            RETRY;
        ENDIF
    ENDPROC

    PROC reset()
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
        WaitTime 0.3;
        StopMove;
        TPWrite "stopped " \Bool:=IsStopMoveAct(\FromMoveTask);
        ! StopMoveReset resets the stop-move state without starting any movement
        ! (it would go on at the next program start): the robot still stands.
        StopMoveReset;
        TPWrite "after StopMoveReset " \Bool:=IsStopMoveAct(\FromMoveTask);
        WaitTime 0.2;
        StorePath;
        here := CRobT(\Tool:=tool0);
        TPWrite "stored at x " \Num:=here.trans.x;
        RestoPath;
        StartMove;
        ! It stood 0.3 s to 0.5 s: 1.06 + 0.2 = 1.26 s.
        WaitRob \InPos;
        TPWrite "arrived after " + NumToStr(ClkRead(c), 2);
    ENDPROC

    PROC retried()
        VAR num d := 0;
        VAR num q;
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL \Conc, Offs(p0, 100, 0, 0), v100, fine, tool0;
        WaitTime 0.3;
        StopMove;
        q := 10 / d;
        TPWrite "q " \Num:=q;
        ! Stopped 0.3 s to 0.4 s: 1.06 + 0.1 = 1.16 s.
        WaitRob \InPos;
        TPWrite "arrived after " + NumToStr(ClkRead(c), 2);
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            d := 2;
            WaitTime 0.1;
            StartMoveRetry;
        ENDIF
    ENDPROC
ENDMODULE
