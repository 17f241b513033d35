MODULE motion_indep_reset
    ! IndReset moves axis 6's measuring system by whole turns (IRB 120: working
    ! range -400..400 degrees); the axis does not move. Worked by hand:
    !  - at 370, \RefNum:=0 \Short: within 0 +- 180, 370 - 360 = 10;
    !  - at 200, \Short (reference 0): 200 is 200 away, 200 - 360 = -160 is 160
    !    away: -160;
    !  - at -100, \RefNum:=0 \Fwd: in [0, 360): -100 + 360 = 260;
    !  - at 300, \RefNum:=90 \Bwd: in (-270, 90]: 300 - 360 = -60;
    !  - at 370, IndReset alone (\Old): stays 370; the axis is in normal mode
    !    again, so IndInpos raises ERR_AXIS_IND;
    !  - a reference without \Short, \Fwd or \Bwd, a reference outside -400..400,
    !    and the robtarget forms on a robot axis: ERR_ARGVALERR;
    !  - at 750, IndReset \Old: outside the working range, execution stops.
    VAR jointtarget j;
    VAR robtarget p := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        IndAMove ROB_1, 6 \ToAbsNum:=370, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=0 \Short;
        Show "370, RefNum 0 Short: ";
        IndAMove ROB_1, 6 \ToAbsNum:=200, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \Short;
        Show "200, Short: ";
        IndAMove ROB_1, 6 \ToAbsNum:=-100, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=0 \Fwd;
        Show "-100, RefNum 0 Fwd: ";
        IndAMove ROB_1, 6 \ToAbsNum:=300, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=90 \Bwd;
        Show "300, RefNum 90 Bwd: ";
        IndAMove ROB_1, 6 \ToAbsNum:=370, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6;
        Show "370, Old: ";
        TPWrite "in position " \Bool:=IndInpos(ROB_1, 6);
        IndAMove ROB_1, 6 \ToAbsNum:=0, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=0;
        IndReset ROB_1, 6 \RefNum:=500 \Short;
        IndReset ROB_1, 6 \RefPos:=p \Short;
        IndAMove ROB_1, 6 \ToAbsPos:=p, 100;
        IndRMove ROB_1, 6 \ToRelPos:=p \Short, 100;
        IndAMove ROB_1, 6 \ToAbsNum:=750, 420;
        WaitUntil IndInpos(ROB_1, 6);
        TPWrite "at 750";
        IndReset ROB_1, 6;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "ERR_ARGVALERR";
            TRYNEXT;
        ELSEIF ERRNO = ERR_AXIS_IND THEN
            TPWrite "ERR_AXIS_IND";
            TRYNEXT;
        ENDIF
    ENDPROC

    PROC Show(string what)
        j := CJointT();
        TPWrite what \Num:=Round(j.robax.rax_6 \Dec:=2);
    ENDPROC
ENDMODULE
