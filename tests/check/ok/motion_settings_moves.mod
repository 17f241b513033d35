MODULE motion_settings_moves
    ! Motion settings and the basic move instructions for a machine
    ! loading robot: MoveAbsJ to joint targets, MoveJ/MoveL/MoveC,
    ! configuration supervision, velocity/acceleration limits and
    ! singularity handling. Ends with a reach check via CalcJointT.

    PERS tooldata tTwinGrip:=[TRUE,[[0,-85,210],[1,0,0,0]],[7.2,[0,-40,95],[1,0,0,0],0.08,0.07,0.05]];
    PERS wobjdata wobjLathe:=[FALSE,TRUE,"",[[1650,-120,1010],[0.5,-0.5,0.5,-0.5]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget jHome:=[[0,-30,30,0,60,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pChuckApproach:=[[0,0,-250],[1,0,0,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pChuck:=[[0,0,-42.5],[1,0,0,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pArcVia:=[[300,400,800],[0,0.707107,0.707107,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pArcEnd:=[[0,650,800],[0,0.707107,0.707107,0],[1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    VAR jointtarget jNow;
    VAR robtarget pNow;
    VAR errnum enReach;
    VAR num nMaxSpeed;

    PROC main()
        motion_defaults;
        MoveAbsJ jHome\NoEOffs,v1000,z50,tTwinGrip;
        load_lathe;
        swing_to_buffer;
        MoveAbsJ jHome,v1000,fine,tTwinGrip;
        report_position;
    ENDPROC

    PROC motion_defaults()
        VelSet 80,2000;
        AccSet 70,70;
        ConfJ\On;
        ConfL\On;
        SingArea\Off;
        nMaxSpeed:=MaxRobSpeed();
    ENDPROC

    PROC load_lathe()
        ! Near the chuck the wrist passes a singularity: let the
        ! controller adjust the orientation and skip config checks
        SingArea\Wrist;
        ConfL\Off;
        MoveJ pChuckApproach,v1500,z20,tTwinGrip\WObj:=wobjLathe;
        AccSet 30,30;
        MoveL pChuck,v100\V:=40,fine\Inpos:=inpos20,tTwinGrip\WObj:=wobjLathe;
        WaitTime\InPos,0.5;
        MoveL pChuckApproach,v800,z20\Z:=35,tTwinGrip\WObj:=wobjLathe;
        AccSet 70,70;
        ConfL\On;
        SingArea\Off;
    ENDPROC

    PROC swing_to_buffer()
        ! Continuous motion while the next instructions run
        MoveJ\Conc,Offs(pArcVia,0,0,100),v2000,z100,tTwinGrip;
        MoveC pArcVia,pArcEnd,v1000\T:=1.8,z50,tTwinGrip;
        MoveL Offs(pArcEnd,0,0,-200),v500,fine,tTwinGrip;
        MoveL Offs(pArcEnd,0,0,-200),v500,fine,tTwinGrip\TLoad:=load0;
    ENDPROC

    PROC report_position()
        jNow:=CJointT();
        pNow:=CRobT(\Tool:=tTwinGrip\WObj:=wobj0);
        TPWrite "Axis 1: "\Num:=jNow.robax.rax_1;
        TPWrite "Axis 5: "\Num:=jNow.robax.rax_5;
        TPWrite "TCP: "\Pos:=pNow.trans;
        TPWrite "cf1/cf4/cf6: "+NumToStr(pNow.robconf.cf1,0)+"/"+NumToStr(pNow.robconf.cf4,0)+"/"+NumToStr(pNow.robconf.cf6,0);
        TPWrite "Max TCP speed: "\Num:=nMaxSpeed;
        IF reachable(pChuck) TPWrite "Chuck position reachable";
    ENDPROC

    ! Check a target with CalcJointT before moving there
    FUNC bool reachable(robtarget target)
        VAR jointtarget jt;
        jt:=CalcJointT(target,tTwinGrip\WObj:=wobjLathe\ErrorNumber:=enReach);
        IF enReach=ERR_ROBLIMIT OR enReach=ERR_OUTSIDE_REACH RETURN FALSE;
        RETURN jt.robax.rax_1>-170 AND jt.robax.rax_1<170;
    ENDFUNC

ENDMODULE
