MODULE MainModule
    ! Moves all parts from the input tray to the output tray.
    ! Data is in CellData, gripper handling in GripperModule.

    PROC main()
        grip_init;
        grip_open;
        MoveAbsJ jHome\NoEOffs,v1000,z50,tGripper;
        FOR row FROM 1 TO TRAY_ROWS DO
            FOR col FROM 1 TO TRAY_COLS DO
                transfer_part row,col;
            ENDFOR
        ENDFOR
        MoveAbsJ jHome\NoEOffs,v1000,fine,tGripper;
        TPWrite "Parts moved in total: "\Num:=nPartsTotal;
    ENDPROC

    PROC transfer_part(num row,num col)
        VAR robtarget pSlot;
        pSlot:=tray_slot(row,col);
        MoveJ Offs(pSlot,0,0,APPROACH_Z),v1500,z20,tGripper\WObj:=wobjTrayIn;
        MoveL pSlot,v200,fine,tGripper\WObj:=wobjTrayIn;
        grip_close;
        MoveL Offs(pSlot,0,0,APPROACH_Z),v800,z20,tGripper\WObj:=wobjTrayIn;
        IF NOT grip_has_part() THEN
            TPWrite "Part lost at row/col "+NumToStr(row,0)+"/"+NumToStr(col,0);
            RETURN;
        ENDIF
        MoveJ Offs(pSlot,0,0,APPROACH_Z),v1500,z20,tGripper\WObj:=wobjTrayOut;
        MoveL pSlot,v200,fine,tGripper\WObj:=wobjTrayOut;
        grip_open;
        MoveL Offs(pSlot,0,0,APPROACH_Z),v800,z20,tGripper\WObj:=wobjTrayOut;
        nPartsTotal:=nPartsTotal+1;
    ENDPROC

ENDMODULE
