MODULE motion_clearpath_pending
    ! ClearPath in a trap while a fly-by MoveLDO still waits for its successor (no
    ! StopMove first): the move and its output are dropped, so the next move must
    ! not set the dropped move's output (doMark stays 0).
    VAR intnum tick;
    VAR signaldo doMark;
    PROC main()
        AliasIO "doMark", doMark;
        CONNECT tick WITH stopIt;
        MoveL [[300,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v500, fine, tool0;
        ITimer \Single, 0.2, tick;
        MoveLDO [[300,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, z50, tool0, doMark, 1;
        MoveL [[400,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
        TPWrite "mark " \Num:=doMark;
    ENDPROC
    TRAP stopIt
        ClearPath;
    ENDTRAP
ENDMODULE
