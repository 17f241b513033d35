MODULE welding
    !-----------------------------------------------------------------
    ! Arc welding a bracket. The seam runs 200 mm straight along the
    ! bracket, then half way round a boss (radius 40 mm) in one MoveC.
    ! The arc is switched on where the seam starts and off where it
    ! ends by TriggIO on the path; a world zone sets doAtCleaner while
    ! the torch is at the nozzle-cleaning station.
    !-----------------------------------------------------------------

    ! A straight torch, 150 mm from the flange, pointing down in the weld.
    PERS tooldata tTorch := [TRUE,[[0,0,150],[1,0,0,0]],[1.2,[0,0,60],[1,0,0,0],0,0,0]];
    ! The bracket's fixture: the seam starts at its origin.
    PERS wobjdata wobjBracket := [FALSE,TRUE,"",[[300,-100,200],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget jHome := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! The torch above the cleaner, and home as a TCP position (world).
    CONST robtarget pCleaner := [[200,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pHome := [[302,0,408],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ! The seam, in the bracket's frame.
    CONST robtarget pSeamStart := [[0,0,0],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pSeamEnd := [[0,200,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pBossTop := [[40,240,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pBossEnd := [[80,200,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    ! Welding speed 20 mm/s.
    CONST speeddata vWeld := [20,500,5000,1000];
    CONST num nApproach := 50;

    VAR triggdata arcOn;
    VAR triggdata arcOff;
    VAR shapedata cleanerVolume;
    VAR wztemporary cleanerZone;
    VAR num seamTime;
    VAR clock weldClock;

    PROC main()
        Reset doArcOn;
        DefineCleanerZone;
        MoveAbsJ jHome, v1000, fine, tTorch;
        WeldBracket;
        CleanNozzle;
        MoveL pHome, v500, fine, tTorch;
        TPWrite "Seam welded in " \Num:=seamTime;
    ENDPROC

    PROC DefineCleanerZone()
        ! A 100 mm cube around the cleaner's nozzle position (world).
        WZBoxDef \Inside, cleanerVolume, [150,200,250], [250,300,350];
        WZDOSet \Temp, cleanerZone \Inside, cleanerVolume, doAtCleaner, 1;
    ENDPROC

    PROC WeldBracket()
        MoveL Offs(pSeamStart, 0, 0, nApproach), v500, fine, tTorch \WObj:=wobjBracket;
        MoveL pSeamStart, v100, fine, tTorch \WObj:=wobjBracket;
        ! The arc strikes where the seam starts and goes out where it ends.
        TriggIO arcOn, 0 \Start \DOp:=doArcOn, 1;
        TriggIO arcOff, 0 \DOp:=doArcOn, 0;
        ClkReset weldClock;
        ClkStart weldClock;
        TriggL pSeamEnd, vWeld, arcOn, z1, tTorch \WObj:=wobjBracket;
        TriggC pBossTop, pBossEnd, vWeld, arcOff, fine, tTorch \WObj:=wobjBracket;
        ClkStop weldClock;
        seamTime := ClkRead(weldClock);
        MoveL Offs(pBossEnd, 0, 0, nApproach), v200, fine, tTorch \WObj:=wobjBracket;
    ENDPROC

    PROC CleanNozzle()
        MoveL pCleaner, v500, fine, tTorch;
        WaitTime 1;
    ENDPROC
ENDMODULE
