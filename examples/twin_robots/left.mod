MODULE Left
    !-----------------------------------------------------------------
    ! The left robot of a pair carrying a part: lift it 100 mm, carry it
    ! 150 mm, put it down, in synchronized movement with the right one.
    !-----------------------------------------------------------------
    VAR syncident syncCarry;
    VAR syncident syncDone;
    PERS tasks pair{2} := [["T_ROB1"],["T_ROB2"]];
    CONST jointtarget jStart := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR robtarget pGrip;
    VAR clock carry;

    PROC main()
        ConfL \Off;
        MoveAbsJ jStart, v1000, fine, tool0;
        pGrip := CRobT(\Tool:=tool0);
        SyncMoveOn syncCarry, pair;
        ClkStart carry;
        MoveL Offs(pGrip, 0, 0, 100) \ID:=10, v200, fine, tool0;
        MoveL Offs(pGrip, 0, 150, 100) \ID:=20, v200, fine, tool0;
        MoveL Offs(pGrip, 0, 150, 0) \ID:=30, v200, fine, tool0;
        ClkStop carry;
        SyncMoveOff syncDone;
        TPWrite "T_ROB1 carried the part in " \Num:=ClkRead(carry);
    ENDPROC
ENDMODULE
