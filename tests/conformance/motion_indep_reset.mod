MODULE motion_indep_reset
    ! IndReset's options move only the logical position of axis 6 (IRB 120: working
    ! range ±400 deg) by whole turns. Worked by hand:
    !  - at 750, \RefNum:=0 \Short: within ±180 of 0: 750 - 2·360 = 30 (the manual's
    !    own example);
    !  - 30 + 720 = 750, \RefNum:=300 \Short: 750 - 300 = 450 = 1.25 turns, rounded to
    !    one turn: 750 - 360 = 390;
    !  - 390 + 360 = 750, \RefNum:=-100 \Fwd: in [-100, 260): 750 - 720 = 30;
    !  - 30 + 720 = 750, \RefNum:=100 \Bwd: in (-260, 100]: 750 - 720 = 30;
    !  - 30 + 300 = 330, \Old: stays 330;
    !  - a reference outside the working range, and \RefNum without \Short, \Fwd or
    !    \Bwd: ERR_AXIS_PAR.
    VAR jointtarget j;

    PROC main()
        MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        IndAMove ROB_1, 6 \ToAbsNum:=750, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=0 \Short;
        Show "short to 0";
        IndDMove ROB_1, 6, 720, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=300 \Short;
        Show "short to 300";
        IndDMove ROB_1, 6, 360, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=-100 \Fwd;
        Show "forward from -100";
        IndDMove ROB_1, 6, 720, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=100 \Bwd;
        Show "backward from 100";
        IndDMove ROB_1, 6, 300, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \Old;
        Show "old";
        IndDMove ROB_1, 6, 10, 420;
        WaitUntil IndInpos(ROB_1, 6);
        IndReset ROB_1, 6 \RefNum:=500 \Short;
        IndReset ROB_1, 6 \RefNum:=0;
    ERROR
        IF ERRNO = ERR_AXIS_PAR THEN
            TPWrite "ERR_AXIS_PAR";
            TRYNEXT;
        ENDIF
    ENDPROC

    PROC Show(string what)
        j := CJointT();
        TPWrite what + ": " \Num:=Round(j.robax.rax_6 \Dec:=2);
    ENDPROC
ENDMODULE
