MODULE motion_settings_errors
    ! Argument checks of the motion settings, each handled in an ERROR handler; a
    ! refused instruction leaves the setting as it was.
    ! SpeedRefresh outside 0..100 % raises ERR_SPEED_REFRESH_LIM (SpeedRefresh page).
    ! uncertain (rapid-vm builtins/motion/settings.rs): VelSet with an Override or Max
    ! of 0 or less, AccSet values above the documented maximum of 100 %, PathResol
    ! outside its documented 25..400 % and GripLoad with a negative mass raise
    ! ERR_ARGVALERR.
    PERS loaddata negative := [-1, [0, 0, 0], [1, 0, 0, 0], 0, 0, 0];

    PROC try_vel(num oride, num max)
        VelSet oride, max;
        TPWrite "VelSet ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "VelSet ERR_ARGVALERR";
        RETURN;
    ENDPROC

    PROC try_acc(num acc, num ramp, num fine)
        AccSet acc, ramp \FinePointRamp:=fine;
        TPWrite "AccSet ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "AccSet ERR_ARGVALERR";
        RETURN;
    ENDPROC

    PROC try_resol(num percent)
        PathResol percent;
        TPWrite "PathResol ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "PathResol ERR_ARGVALERR";
        RETURN;
    ENDPROC

    PROC try_refresh(num percent)
        SpeedRefresh percent;
        TPWrite "SpeedRefresh ok";
    ERROR
        IF ERRNO = ERR_SPEED_REFRESH_LIM TPWrite "SpeedRefresh ERR_SPEED_REFRESH_LIM";
        RETURN;
    ENDPROC

    PROC main()
        try_vel 0, 1000;
        try_vel 50, -1;
        try_vel 150, 1000;
        TPWrite "vel " + ValToStr(C_MOTSET.vel);
        try_acc 101, 50, 50;
        try_acc 50, 150, 50;
        try_acc 50, 50, 100.5;
        try_acc 100, 100, 0;
        TPWrite "acc " + ValToStr(C_MOTSET.acc);
        try_resol 24;
        try_resol 401;
        try_resol 25;
        try_resol 400;
        TPWrite "resol " + ValToStr(C_MOTSET.pathresol);
        try_refresh 100.5;
        try_refresh -1;
        try_refresh 0;
        try_refresh 100;
        TPWrite "task override " \Num:=CSpeedOverride(\CTask);
        GripLoad negative;
        TPWrite "GripLoad ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "GripLoad ERR_ARGVALERR";
        RETURN;
    ENDPROC
ENDMODULE
