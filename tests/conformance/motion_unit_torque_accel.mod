MODULE motion_unit_torque_accel
    ! GetMotorTorque while the robot accelerates its load (default IRB 120). The tool's
    ! load, 1 kg 100 mm out on the flange z axis, sits at [474, 0, 630] at all axes 0:
    ! 474 mm from axis 1, which gravity does not load (it turns about the vertical).
    ! MoveAbsJ turning axis 1 by 90° ramps it up at 250 °/s per 0.15 s, i.e.
    ! 1666.67 °/s² = 29.0888 rad/s²; its TCP chord (529 mm at v1000) caps the cruise
    ! at 170 °/s, which it reaches after 0.102 s. 0.05 s in, the load needs m·r·α
    ! tangentially: axis 1 gives 1 · 0.474² · 29.0888 = 6.5356 Nm.
    PERS tooldata heavy := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 100], [1, 0, 0, 0], 0, 0, 0]];
    CONST jointtarget zero := [[0, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget turned := [[90, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveAbsJ zero, v1000, fine, heavy;
        TPWrite "standing " + NumToStr(GetMotorTorque(1), 2);
        MoveAbsJ \Conc, turned, v1000, fine, heavy;
        WaitTime 0.05;
        TPWrite "accelerating " + NumToStr(GetMotorTorque(1), 2);
    ENDPROC
ENDMODULE
