MODULE positioner
    !-----------------------------------------------------------------
    ! T_STN1 moves turntable STN1 only. It turns the part while the robot
    ! stands clear (semi-coordinated), and turns it back in step with the
    ! robot's weld (synchronized movement: the moves of \ID 10 start
    ! together and take the time the slower needs).
    !-----------------------------------------------------------------

    PERS tasks tCell{2} := [["T_ROB1"],["T_STN1"]];
    VAR syncident sTurn;
    VAR syncident sTurned;
    VAR syncident sWeld;
    VAR syncident sWelded;

    CONST jointtarget jSideA := [[9E9,9E9,9E9,9E9,9E9,9E9],[0,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jSideB := [[9E9,9E9,9E9,9E9,9E9,9E9],[180,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        WaitSyncTask sTurn, tCell;
        MoveExtJ jSideB, v1000, fine;
        WaitSyncTask sTurned, tCell;
        SyncMoveOn sWeld, tCell;
        MoveExtJ jSideA \ID:=10, v1000, fine;
        SyncMoveOff sWelded;
    ENDPROC
ENDMODULE
