MODULE motion_settings
    ! Motion settings read back through C_MOTSET and CSpeedOverride (manual 1.7: "the
    ! general motion settings can be read through the system variables C_MOTSET and
    ! C_PROGDISP"). The defaults are what SYS_RESET sets (motsetdata page): vel
    ! [100,5000] (uncertain: RW6 documents vmax.v_tcp as Max), acc [100,100,100],
    ! sing all FALSE, conf [TRUE,TRUE,30,45,90], pathresol 100, cirpathreori 0.
    PERS loaddata piece := [2.5, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0];

    PROC show(string label)
        TPWrite label + " vel " + ValToStr(C_MOTSET.vel) + " acc " + ValToStr(C_MOTSET.acc);
        TPWrite label + " sing " + ValToStr(C_MOTSET.sing) + " conf " + ValToStr(C_MOTSET.conf);
        TPWrite label + " resol " + ValToStr(C_MOTSET.pathresol) + " cir " + ValToStr(C_MOTSET.cirpathreori);
    ENDPROC

    PROC main()
        VAR motsetdata before;
        before := C_MOTSET;
        show "default";
        TPWrite "override " \Num:=CSpeedOverride();
        TPWrite "task override " \Num:=CSpeedOverride(\CTask);
        VelSet 50, 800;
        ! AccSet: Acc below 20 % gives 20 %, Ramp below 10 % gives 10 %, and
        ! FinePointRamp takes the Ramp value when left out (AccSet page).
        AccSet 10, 5;
        ConfJ \Off;
        ConfL \Off;
        SingArea \Wrist;
        PathResol 250;
        CirPathMode \CirPointOri;
        show "changed";
        AccSet 60, 40 \FinePointRamp:=5;
        SingArea \LockAxis4;
        ConfJ \On;
        CirPathMode \Wrist56;
        show "again";
        ! SpeedRefresh sets the task's override; the operator's stays 100.
        SpeedRefresh 40;
        TPWrite "override " \Num:=CSpeedOverride();
        TPWrite "task override " \Num:=CSpeedOverride(\CTask);
        ! GripLoad and CornerPathWarning are kept by the controller but not readable.
        GripLoad piece;
        GripLoad load0;
        CornerPathWarning FALSE;
        CornerPathWarning TRUE;
        ! Setting every value back to its default gives the first C_MOTSET again.
        VelSet 100, 5000;
        AccSet 100, 100;
        ConfJ \On;
        ConfL \On;
        SingArea \Off;
        PathResol 100;
        CirPathMode;
        show "reset";
        TPWrite "same " \Bool:=(before = C_MOTSET);
    ENDPROC
ENDMODULE
