MODULE motion_indep_axes
    ! Axis 6 in independent mode (IRB 120: max 420 deg/s, reached in 0.15 s, so
    ! 2800 deg/s² at \Ramp 100). Worked by hand:
    !  - IndAMove to 90 deg at 100 deg/s from 0: ramps of 100/2800 = 0.0357 s over
    !    1.786 deg each, 86.43 deg at 100 deg/s in 0.8643 s: 0.9357 s in all; half way
    !    (0.5 s) it is not in position; after WaitTime 0.5 more it is, at 90;
    !  - IndDMove -30 at 420 deg/s: a triangle (30 < 420²/2800 = 63 deg): peak
    !    √(2800 · 30) = 289.8 deg/s, 2 · 0.1035 = 0.207 s; at 60 after WaitTime 0.3;
    !  - IndRMove \ToRelNum:=350 \Short from 60: 70 deg backwards (not 290 forwards),
    !    to -10; \Fwd to 20 from -10: +30 → 20;
    !  - IndCMove at 200 deg/s: after 1 s it has turned 200 · (1 - 0.0714/2) = 192.86
    !    deg (ramp 200/2800 = 0.0714 s) and is at speed; IndReset refuses a turning
    !    axis, so it is sent back by IndAMove to 0 first (from 212.86: 212.86 deg at
    !    420 deg/s: 0.5068 + 0.15 = 0.657 s), then IndReset;
    !  - axis 2 cannot move independently: ERR_AXIS_PAR.
    VAR jointtarget j;

    PROC main()
        MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        IndAMove ROB_1, 6 \ToAbsNum:=90, 100;
        WaitTime 0.5;
        TPWrite "in position at 0.5 s " \Bool:=IndInpos(ROB_1, 6);
        TPWrite "at speed " \Bool:=IndSpeed(ROB_1, 6 \InSpeed);
        WaitTime 0.5;
        j := CJointT();
        TPWrite "axis 6 " \Num:=Round(j.robax.rax_6 \Dec:=2);
        TPWrite "in position " \Bool:=IndInpos(ROB_1, 6);
        TPWrite "stands " \Bool:=IndSpeed(ROB_1, 6 \ZeroSpeed);
        IndDMove ROB_1, 6, -30, 420;
        WaitTime 0.3;
        j := CJointT();
        TPWrite "after -30: " \Num:=Round(j.robax.rax_6 \Dec:=2);
        IndRMove ROB_1, 6 \ToRelNum:=350 \Short, 100;
        WaitTime 2;
        j := CJointT();
        TPWrite "short way: " \Num:=Round(j.robax.rax_6 \Dec:=2);
        IndRMove ROB_1, 6 \ToRelNum:=20 \Fwd, 100;
        WaitTime 2;
        j := CJointT();
        TPWrite "forward: " \Num:=Round(j.robax.rax_6 \Dec:=2);
        IndCMove ROB_1, 6, 200;
        WaitTime 1;
        j := CJointT();
        TPWrite "turned to " \Num:=Round(j.robax.rax_6 \Dec:=2);
        TPWrite "at speed " \Bool:=IndSpeed(ROB_1, 6 \InSpeed);
        IndAMove ROB_1, 6 \ToAbsNum:=0, 420;
        WaitTime 0.7;
        IndReset ROB_1, 6;
        MoveAbsJ [[0,0,0,0,30,45],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
        j := CJointT();
        TPWrite "normal again: " \Num:=Round(j.robax.rax_6 \Dec:=2);
        IndCMove ROB_1, 2, 10;
    ERROR
        IF ERRNO = ERR_AXIS_PAR THEN
            TPWrite "ERR_AXIS_PAR";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
