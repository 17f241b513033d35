MODULE draft_station_with_placeholder
    ! Station 8 (screw feeding) is still being programmed on the
    ! FlexPendant. The new routine contains an instruction placeholder
    ! that the programmer has not filled in yet. The module loads,
    ! and only executing the placeholder would give ERR_EXECPHR.

    PERS tooldata tScrewdriver:=[TRUE,[[0,0,278],[1,0,0,0]],[3.4,[0,0,120],[1,0,0,0],0.03,0.03,0.01]];
    CONST robtarget pFeeder:=[[420,-640,505],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pHole1:=[[880,-60,380],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pHole2:=[[880,60,380],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR signaldo do_vacuum_bit;
    VAR signaldi di_screw_ready;
    VAR num nScrews:=0;

    PROC main()
        AliasIO "DO_VacuumBit",do_vacuum_bit;
        AliasIO "DI_ScrewReady",di_screw_ready;
        ! Station 7 program, finished and in production
        screw_hole pHole1;
        screw_hole pHole2;
        TPWrite "Screws set: "\Num:=nScrews;
    ENDPROC

    PROC screw_hole(robtarget hole)
        fetch_screw;
        MoveJ Offs(hole,0,0,60),v1000,z20,tScrewdriver;
        MoveL Offs(hole,0,0,5),v200,z1,tScrewdriver;
        MoveL hole,v20,fine,tScrewdriver;
        WaitTime 1.5;
        Reset do_vacuum_bit;
        MoveL Offs(hole,0,0,60),v500,z20,tScrewdriver;
        nScrews:=nScrews+1;
    ENDPROC

    PROC fetch_screw()
        WaitDI di_screw_ready,1;
        MoveJ Offs(pFeeder,0,0,40),v1000,z10,tScrewdriver;
        MoveL pFeeder,v100,fine,tScrewdriver;
        Set do_vacuum_bit;
        WaitTime 0.3;
        MoveL Offs(pFeeder,0,0,40),v300,z10,tScrewdriver;
    ENDPROC

    ! New routine for station 8 - work in progress
    PROC station8_cover_screws()
        fetch_screw;
        MoveJ Offs(pHole1,250,0,60),v1000,z20,tScrewdriver;
        <SMT>
        MoveL Offs(pHole1,250,0,60),v500,z20,tScrewdriver;
    ENDPROC

ENDMODULE
