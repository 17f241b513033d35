MODULE vision_offsets_utf8_bom
    ! File saved by a PC editor with a UTF-8 byte order mark.
    ! Applies 2-D vision offsets (dx, dy, rz) from a camera PLC to
    ! the taught pick position, with plausibility limits.

    PERS tooldata tVacCup:=[TRUE,[[0,0,132],[1,0,0,0]],[0.9,[0,0,60],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjBelt:=[FALSE,TRUE,"",[[300,-950,640],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    CONST robtarget pTaughtPick:=[[250,0,0],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    CONST num MAX_SHIFT:=40;
    CONST num MAX_ROT:=30;
    VAR num nDx:=0;
    VAR num nDy:=0;
    VAR num nRz:=0;
    VAR signalgi gi_dx;
    VAR signalgi gi_dy;
    VAR signalgi gi_rz;
    VAR signaldi di_result_valid;
    VAR signaldo do_trigger;

    PROC main()
        AliasIO "GI_CamDx",gi_dx;
        AliasIO "GI_CamDy",gi_dy;
        AliasIO "GI_CamRz",gi_rz;
        AliasIO "DI_CamValid",di_result_valid;
        AliasIO "DO_CamTrigger",do_trigger;
        FOR i FROM 1 TO 10 DO
            IF get_offsets() THEN
                pick_with_offset;
            ELSE
                TPWrite "Vision result rejected";
            ENDIF
        ENDFOR
    ENDPROC

    ! Values arrive as unsigned 16 bit with +1000 bias, tenths of mm/deg
    FUNC bool get_offsets()
        PulseDO\PLength:=0.05,do_trigger;
        WaitDI di_result_valid,1\MaxTime:=2;
        nDx:=(GInput(gi_dx)-1000)/10;
        nDy:=(GInput(gi_dy)-1000)/10;
        nRz:=(GInput(gi_rz)-1000)/10;
        IF Abs(nDx)>MAX_SHIFT OR Abs(nDy)>MAX_SHIFT RETURN FALSE;
        IF Abs(nRz)>MAX_ROT RETURN FALSE;
        RETURN TRUE;
    ERROR
        IF ERRNO=ERR_WAIT_MAXTIME RETURN FALSE;
        RAISE;
    ENDFUNC

    PROC pick_with_offset()
        VAR robtarget pPick;
        pPick:=RelTool(Offs(pTaughtPick,nDx,nDy,0),0,0,0\Rz:=nRz);
        MoveJ Offs(pPick,0,0,80),v1500,z20,tVacCup\WObj:=wobjBelt;
        MoveL pPick,v300,fine,tVacCup\WObj:=wobjBelt;
        WaitTime 0.1;
        MoveL Offs(pPick,0,0,80),v1500,z20,tVacCup\WObj:=wobjBelt;
    ENDPROC

ENDMODULE
