MODULE Right
    !-----------------------------------------------------------------
    ! The right robot of the pair: lift 100 mm, carry only 100 mm (its part
    ! of the load is nearer), put it down, synchronized with the left one.
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
        MoveL Offs(pGrip, 0, 100, 100) \ID:=20, v200, fine, tool0;
        MoveL Offs(pGrip, 0, 100, 0) \ID:=30, v200, fine, tool0;
        ClkStop carry;
        SyncMoveOff syncDone;
        TPWrite "T_ROB2 carried the part in " \Num:=ClkRead(carry);
    ENDPROC
ENDMODULE
