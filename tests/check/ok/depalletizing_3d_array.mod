MODULE depalletizing_3d_array
    ! Depalletizing of brake discs from a wire-mesh box.
    ! The box holds LAYERS x ROWS x COLS discs. Positions are kept in a
    ! 3-D array that is (re)calculated from a measured box corner, then
    ! emptied top layer first with FOR loops counting down.

    PERS tooldata tMagnet:=[TRUE,[[0,-12,162],[1,0,0,0]],[4.1,[0,0,70],[1,0,0,0],0.02,0.02,0.01]];
    PERS wobjdata wobjBox:=[FALSE,TRUE,"",[[-350,-1250,410],[0.707107,0,0,0.707107]],[[0,0,0],[1,0,0,0]]];
    PERS loaddata loadDisc:=[9.3,[0,0,20],[1,0,0,0],0.06,0.06,0.11];

    CONST robtarget pBoxCorner:=[[160,160,0],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pLatheLoad:=[[1320,210,985],[0.5,0.5,0.5,0.5],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget jSafe:=[[-90,-20,30,0,80,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    ! box{layer,row,col}
    VAR robtarget pDisc{4,3,3};
    VAR bool bTaken{4,3,3};
    PERS num nDiscPitch:=310;
    PERS num nLayerPitch:=64.5;

    VAR signaldo do_magnet;
    VAR signaldi di_disc_on_magnet;

    PROC main()
        AliasIO "DO_Magnet",do_magnet;
        AliasIO "DI_DiscDetected",di_disc_on_magnet;
        MoveAbsJ jSafe\NoEOffs,v1000,z50,tMagnet;
        calc_box_positions pDisc,nDiscPitch,nLayerPitch;
        reset_taken bTaken;
        empty_box;
        MoveAbsJ jSafe\NoEOffs,v1000,fine,tMagnet;
    ENDPROC

    ! Calculate every disc position; the array size is read with Dim
    PROC calc_box_positions(VAR robtarget box{*,*,*},num pitch,num layer_pitch)
        VAR num top;
        top:=Dim(box,1);
        FOR l FROM 1 TO Dim(box,1) DO
            FOR r FROM 1 TO Dim(box,2) DO
                FOR c FROM 1 TO Dim(box,3) DO
                    box{l,r,c}:=Offs(pBoxCorner,(c-1)*pitch,(r-1)*pitch,(top-l)*layer_pitch);
                ENDFOR
            ENDFOR
        ENDFOR
    ENDPROC

    PROC reset_taken(VAR bool flags{*,*,*})
        FOR l FROM 1 TO Dim(flags,1) DO
            FOR r FROM 1 TO Dim(flags,2) DO
                FOR c FROM 1 TO Dim(flags,3) DO
                    flags{l,r,c}:=FALSE;
                ENDFOR
            ENDFOR
        ENDFOR
    ENDPROC

    PROC empty_box()
        ! Layer 1 is the top layer; rows are taken from the far side
        FOR l FROM 1 TO 4 DO
            FOR r FROM 3 TO 1 STEP -1 DO
                FOR c FROM 1 TO 3 STEP 1 DO
                    IF NOT bTaken{l,r,c} THEN
                        pick_disc l,r,c;
                        load_lathe;
                    ENDIF
                ENDFOR
            ENDFOR
        ENDFOR
    ENDPROC

    PROC pick_disc(num l,num r,num c)
        MoveJ Offs(pDisc{l,r,c},0,0,300),v1500,z50,tMagnet\WObj:=wobjBox;
        MoveL Offs(pDisc{l,r,c},0,0,15),v500,z5,tMagnet\WObj:=wobjBox;
        MoveL pDisc{l,r,c},v80,fine,tMagnet\WObj:=wobjBox;
        Set do_magnet;
        WaitTime 0.3;
        IF di_disc_on_magnet=0 THEN
            Reset do_magnet;
            TPWrite "No disc at layer/row/col "+NumToStr(l,0)+"/"+NumToStr(r,0)+"/"+NumToStr(c,0);
        ELSE
            GripLoad loadDisc;
        ENDIF
        bTaken{l,r,c}:=TRUE;
        MoveL Offs(pDisc{l,r,c},0,0,300),v800,z50,tMagnet\WObj:=wobjBox;
    ENDPROC

    PROC load_lathe()
        IF DOutput(do_magnet)=1 THEN
            MoveJ Offs(pLatheLoad,-250,0,0),v1500,z20,tMagnet;
            MoveL pLatheLoad,v200,fine,tMagnet;
            Reset do_magnet;
            GripLoad load0;
            MoveL Offs(pLatheLoad,-250,0,0),v1000,z20,tMagnet;
        ENDIF
    ENDPROC

ENDMODULE
