MODULE motion_readback
    ! Where the robot is, read back. IRB 120 (motion.md §2, §5): at all axes 0 the
    ! flange (tool0) is at [374, 0, 630], pointing along +x, orient [0.70711,0,0.70711,0];
    ! the wrist centre is 72 mm behind it, at x = 302.
    CONST jointtarget bent := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget zero := [[0, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    PERS tooldata pen := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [0.5, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];

    PROC main()
        VAR jointtarget jt;
        VAR robtarget here;
        VAR robtarget back;
        VAR pos p;
        here := CalcRobT(zero, tool0);
        TPWrite "calibration position " \Pos:=here.trans;
        TPWrite "cf " + NumToStr(here.robconf.cf1, 0) + NumToStr(here.robconf.cf4, 0) + NumToStr(here.robconf.cf6, 0) + NumToStr(here.robconf.cfx, 0);
        ! A 100 mm tool along the flange's z axis (+x here) reaches 100 mm further.
        here := CalcRobT(zero, pen);
        TPWrite "pen tip " \Pos:=here.trans;
        MoveAbsJ bent, v1000, fine, tool0;
        jt := CJointT();
        TPWrite "axis 5 " \Num:=jt.robax.rax_5;
        ! Axis 5 turns the flange 30 deg down about the wrist centre: x = 302 + 72 cos 30
        ! = 364.354, z = 630 - 72 sin 30 = 594.
        p := CPos(\Tool:=tool0);
        TPWrite "x " + NumToStr(p.x, 3) + " z " + NumToStr(p.z, 3);
        ! CalcJointT brings the robtarget back to the same axis values.
        here := CRobT(\Tool:=tool0 \WObj:=wobj0);
        jt := CalcJointT(here, tool0);
        TPWrite "back to axis 5 " + NumToStr(jt.robax.rax_5, 3) + ", axis 1 " + NumToStr(jt.robax.rax_1, 3);
        ! Out of reach: two metres away.
        back := Offs(here, 2000, 0, 0);
        jt := CalcJointT(back, tool0);
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_OUTSIDE_REACH THEN
            TPWrite "ERR_OUTSIDE_REACH";
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
