MODULE motion_sync_suspend
    ! A task in synchronized movement (a group of one) suspends it on the StorePath
    ! level: there IsSyncMoveOn is FALSE and a move needs no \ID; after SyncMoveResume
    ! it is TRUE again, and the base path is restored.
    VAR syncident sync1;
    VAR syncident sync2;
    PERS tasks me{1} := [["T_ROB1"]];
    CONST robtarget p0 := [[300,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ConfL \Off;
        MoveL p0, v500, fine, tool0;
        SyncMoveOn sync1, me;
        MoveL Offs(p0, 0, 50, 0) \ID:=10, v100, fine, tool0;
        TPWrite "in sync " + ValToStr(IsSyncMoveOn());
        StorePath;
        SyncMoveSuspend;
        TPWrite "suspended " + ValToStr(IsSyncMoveOn());
        MoveL Offs(p0, 0, 50, 50), v100, fine, tool0;
        MoveL Offs(p0, 0, 50, 0), v100, fine, tool0;
        SyncMoveResume;
        TPWrite "resumed " + ValToStr(IsSyncMoveOn());
        RestoPath;
        MoveL p0 \ID:=20, v100, fine, tool0;
        SyncMoveOff sync2;
        TPWrite "off " + ValToStr(IsSyncMoveOn());
    ENDPROC
ENDMODULE
