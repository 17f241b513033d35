MODULE motion_unit_torque
    ! GetMotorTorque and the test signals (manual 1.8, 1.18) on the default IRB 120.
    ! Modelled: the torque each axis gives to hold the tool load and the payload still
    ! against gravity, g = 9.81 (the arm's own link masses are not public). At all
    ! axes 0 the flange is at [374, 0, 630] pointing along +x; axes 2 and 3 turn about
    ! y through x = 0, axis 5 through the wrist centre at x = 302, so a mass m at
    ! x = d needs 9.81 m (d / 1000) Nm, negative (a positive turn lowers it).
    PERS tooldata pen := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
    PERS loaddata piece := [2, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0];
    CONST jointtarget zero := [[0, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget down := [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget turned := [[90, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    VAR intnum tick;
    VAR num moving := -1;

    TRAP read_speed
        moving := TestSignRead(3);
    ENDTRAP

    FUNC num r2(num x)
        RETURN Round(x \Dec:=2) + 0;
    ENDFUNC

    PROC main()
        MoveAbsJ zero, v1000, fine, pen;
        ! Tool load 1 kg at x = 474; payload load0, 0.001 kg at x = 374.001:
        ! axis 2: 9.81 (0.474 + 0.000374) = 4.6536; axis 5: 9.81 (0.172 + 0.000072) = 1.6880.
        TPWrite "axis 2 " \Num:=r2(GetMotorTorque(2));
        TPWrite "axis 3 " \Num:=r2(GetMotorTorque(\MecUnit:=ROB_1, 3));
        TPWrite "axis 5 " \Num:=r2(GetMotorTorque(5));
        TPWrite "axes 1, 4, 6 hold nothing " \Bool:=Abs(GetMotorTorque(1)) < 0.001 AND Abs(GetMotorTorque(4)) < 0.001 AND Abs(GetMotorTorque(6)) < 0.001;
        ! GripLoad: 2 kg at 50 mm along the tool's z, whose TCP is 100 mm out: at
        ! x = 524. Axis 2: 9.81 (0.474 + 2 * 0.524) = 14.9308; axis 5: 9.81 (0.172 +
        ! 2 * 0.222) = 6.0430.
        GripLoad piece;
        TPWrite "with payload, axis 2 " \Num:=r2(GetMotorTorque(2));
        TPWrite "with payload, axis 5 " \Num:=r2(GetMotorTorque(5));
        ! Axis 5 at 90 degrees points the flange down: both loads hang below the wrist
        ! centre (x = 302): axis 2 needs 9.81 * 3 * 0.302 = 8.8879, axis 5 nothing.
        MoveAbsJ down, v1000, fine, pen;
        TPWrite "down, axis 2 " \Num:=r2(GetMotorTorque(2));
        TPWrite "down, axis 5 holds nothing " \Bool:=Abs(GetMotorTorque(5)) < 0.001;
        ! Test signals: the torque reference of axis 2, the motor angle of axis 5
        ! (pi/2) and the speed of axis 1 (0 while the robot stands).
        TestSignDefine 1, torque_ref, ROB_1, 2, 0.004;
        TestSignDefine 2, resolver_angle, ROB_1, 5, 0;
        TestSignDefine 3, speed, ROB_1, 1, 0.1;
        TPWrite "signal 1 " \Num:=r2(TestSignRead(1));
        TPWrite "signal 2 " \Num:=r2(TestSignRead(2));
        TPWrite "signal 3 standing " \Num:=r2(TestSignRead(3));
        TPWrite "signal 4 not defined " \Num:=TestSignRead(4);
        ! Turning axis 1 by 90 degrees: half-way through, it turns forwards, no faster
        ! than its 250 deg/s (4.3633 rad/s).
        ! A timer interrupt reads it 0.2 s into the move.
        CONNECT tick WITH read_speed;
        ITimer \Single, 0.2, tick;
        MoveAbsJ turned, v1000, fine, pen;
        TPWrite "signal 3 moving in (0, 4.3634] " \Bool:=moving > 0 AND moving <= 4.3634;
        TPWrite "signal 3 still again " \Num:=r2(TestSignRead(3));
        TestSignReset;
        TPWrite "after TestSignReset " \Num:=TestSignRead(1);
        GripLoad load0;
        ! Load identification: valid for the robot's tool and payload, not for the
        ! positioner kinds (the unit is a TCP robot).
        TPWrite "tool load id valid " \Bool:=ParIdRobValid(TOOL_LOAD_ID) = ROB_LOAD_VAL;
        TPWrite "payload id valid " \Bool:=ParIdRobValid(PAY_LOAD_ID \MechUnit:=ROB_1) = ROB_LOAD_VAL;
        TPWrite "positioner id not valid " \Bool:=ParIdRobValid(IRBP_K) = ROB_NOT_LOAD_VAL;
        TestSignDefine 13, speed, ROB_1, 1, 0.1;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "channel 13: ERR_ARGVALERR";
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
