MODULE searchl_edge_finding
    ! Finds the real position of a sheet on the welding table with a
    ! touch probe before welding. Two searches in X, one in Y and one
    ! in Z build a corrected work object (program displacement frame).

    PERS tooldata tProbe:=[TRUE,[[0,0,262.35],[1,0,0,0]],[1.4,[0,0,110],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjSheet:=[FALSE,TRUE,"",[[1300,-400,650],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    PERS bool bProbeHit:=FALSE;

    CONST robtarget pSearchX1:=[[-20,50,-5],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pSearchX2:=[[-20,350,-5],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pSearchY:=[[100,-20,-5],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pSearchZ:=[[100,100,30],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR robtarget pHitX1;
    VAR robtarget pHitX2;
    VAR robtarget pHitY;
    VAR robtarget pHitZ;
    VAR signaldi di_probe;
    VAR num nMisses:=0;
    VAR pose peCorrection;

    PROC main()
        AliasIO "DI_TouchProbe",di_probe;
        search_edges;
        apply_correction;
    ENDPROC

    PROC search_edges()
        ! X edge, first point: stop hard on the rising edge
        MoveJ Offs(pSearchX1,-30,0,50),v800,z20,tProbe\WObj:=wobjSheet;
        MoveL Offs(pSearchX1,-30,0,0),v200,fine,tProbe\WObj:=wobjSheet;
        SearchL\Stop,di_probe,pHitX1,Offs(pSearchX1,60,0,0),v20,tProbe\WObj:=wobjSheet;
        MoveL Offs(pHitX1,-10,0,50),v200,z10,tProbe\WObj:=wobjSheet;
        ! X edge, second point: soft stop on the path
        MoveL Offs(pSearchX2,-30,0,0),v200,fine,tProbe\WObj:=wobjSheet;
        SearchL\PStop,di_probe\PosFlank,pHitX2,Offs(pSearchX2,60,0,0),v20,tProbe\WObj:=wobjSheet;
        MoveL Offs(pHitX2,-10,0,50),v200,z10,tProbe\WObj:=wobjSheet;
        ! Y edge with \SStop
        MoveL Offs(pSearchY,0,-30,0),v200,fine,tProbe\WObj:=wobjSheet;
        SearchL\SStop,di_probe,pHitY,Offs(pSearchY,0,60,0),v20,tProbe\WObj:=wobjSheet;
        MoveL Offs(pHitY,0,-10,50),v200,z10,tProbe\WObj:=wobjSheet;
        ! Z surface searched on a persistent bool set by a sensor task
        bProbeHit:=FALSE;
        SearchL\Stop,bProbeHit,pHitZ,Offs(pSearchZ,0,0,-60),v10\V:=5,tProbe\WObj:=wobjSheet;
        MoveL Offs(pHitZ,0,0,50),v200,z10,tProbe\WObj:=wobjSheet;
    ERROR
        IF ERRNO=ERR_WHLSEARCH THEN
            ! No hit: use the nominal point and continue
            nMisses:=nMisses+1;
            TPWrite "Search without hit, nominal position used";
            TRYNEXT;
        ELSEIF ERRNO=ERR_SIGSUPSEARCH THEN
            TPWrite "Probe already active at search start";
            WaitDI di_probe,0\MaxTime:=5;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC apply_correction()
        VAR num nAngle;
        VAR num dx;
        VAR num dy;
        dx:=pHitX2.trans.x-pHitX1.trans.x;
        dy:=pHitX2.trans.y-pHitX1.trans.y;
        nAngle:=ATan2(-dx,dy);
        peCorrection.trans:=[pHitX1.trans.x+20,pHitY.trans.y+20,pHitZ.trans.z-5];
        peCorrection.rot:=OrientZYX(nAngle,0,0);
        PDispSet peCorrection;
        TPWrite "Sheet rotated by [deg]: "\Num:=nAngle;
        TPWrite "Search misses: "\Num:=nMisses;
    ENDPROC

    PROC clear_correction()
        PDispOff;
    ENDPROC

ENDMODULE
