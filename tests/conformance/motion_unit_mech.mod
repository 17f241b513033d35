MODULE motion_unit_mech
    ! Mechanical units (manual 1.8, 1.20). A program run alone is the motion task
    ! T_ROB1 with one TCP robot, ROB_1: six axes, task 1, motion planner 1, always
    ! active (a TCP robot cannot be deactivated, so it is never OK to deactivate).
    ! The robot is the default IRB 120-3/0.58, whose data sheet gives 6.2 m/s as its
    ! maximum TCP speed.
    CONST jointtarget there := [[0, -30, 20, 0, 90, 45], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    FUNC string d4(num x)
        RETURN NumToStr(Round(x \Dec:=4) + 0, 4);
    ENDFUNC

    VAR mecunit unit;

    PROC main()
        VAR num listno := 0;
        VAR string name := "";
        VAR bool tcprob := FALSE;
        VAR num noofaxes := 0;
        VAR num mectaskno := 0;
        VAR num motplanno := 0;
        VAR bool active := FALSE;
        VAR num drivemodule := 0;
        VAR bool oktodeact := TRUE;
        TPWrite "RobName " + RobName();
        TPWrite "MaxRobSpeed " \Num:=MaxRobSpeed();
        TPWrite "MaxRobReorientSpeed " \Num:=MaxRobReorientSpeed();
        WHILE GetNextMechUnit(listno, name \TCPRob:=tcprob \NoOfAxes:=noofaxes \MecTaskNo:=mectaskno \MotPlanNo:=motplanno \Active:=active \DriveModule:=drivemodule \OKToDeact:=oktodeact) DO
            TPWrite name + " next " + NumToStr(listno, 0) + " axes " + NumToStr(noofaxes, 0) + " task " + NumToStr(mectaskno, 0) + " planner " + NumToStr(motplanno, 0) + " drive " + NumToStr(drivemodule, 0);
            TPWrite "tcp robot " \Bool:=tcprob;
            TPWrite "active " \Bool:=active;
            TPWrite "ok to deactivate " \Bool:=oktodeact;
        ENDWHILE
        ! After the last unit: FALSE, and nothing is written.
        TPWrite "list number stays " \Num:=listno;
        TPWrite "a unit the list does not have " \Bool:=GetNextMechUnit(listno, name);
        TPWrite "ROB_1 active " \Bool:=IsMechUnitActive(ROB_1);
        TPWrite "ROB_ID active " \Bool:=IsMechUnitActive(ROB_ID);
        ! \MecRef hands out the unit itself, for the unit functions.
        listno := 0;
        IF GetNextMechUnit(listno, name \MecRef:=unit) TPWrite "MecRef " + name + " active " \Bool:=IsMechUnitActive(unit);
        ! Activating the robot, already active, changes nothing.
        ActUnit ROB_1;
        ! Motor angles in radians: axis 2 at -30 degrees is -pi/6, axis 5 at 90 is
        ! pi/2, axis 6 at 45 is pi/4 (the gear ratios are not public: ratio 1).
        MoveAbsJ there, v1000, fine, tool0;
        TPWrite "motor 2 " + d4(ReadMotor(2));
        TPWrite "motor 5 " + d4(ReadMotor(\MecUnit:=ROB_1, 5));
        TPWrite "motor 6 " + d4(ReadMotor(\MecUnit:=ROB_ID, 6));
        TPWrite "motor 7 " + d4(ReadMotor(7));
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "axis 7: ERR_ARGVALERR";
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
