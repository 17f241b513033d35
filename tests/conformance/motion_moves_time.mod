MODULE motion_moves_time
    ! Move times from the timing model (docs/semantics.md, motion): IRB 120, axis
    ! ramp 0.15 s, TCP acceleration 10 m/s^2, fine-point settle 0.05 s.
    CONST jointtarget bent := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR clock c;

    PROC main()
        ! Axis 5 by 30 deg at 320 deg/s with 2133 deg/s^2: a triangle profile,
        ! 2*sqrt(30/2133.3) = 0.2372 s, plus 0.05 s settle = 0.287 s.
        ClkStart c;
        MoveAbsJ bent, v1000, fine, tool0;
        TPWrite "MoveAbsJ axis 5 by 30: " + NumToStr(ClkRead(c), 3);
        MoveJ p0, v1000, fine, tool0;
        ! 100 mm at 100 mm/s: 100/100 + 100/10000 = 1.01 s, plus 0.05 s settle.
        ClkReset c;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        TPWrite "MoveL 100 mm fine: " + NumToStr(ClkRead(c), 2);
        ! Two 100 mm legs with a 90 deg corner of 10 mm at 100 mm/s: the corner is
        ! walked at full speed (its limit sqrt(10000*10/sin 45) = 376 mm/s), so
        ! 2 * 100/100 + 100/10000 + 0.05 s settle = 2.06 s; as two stop points 2.12 s.
        ClkReset c;
        MoveL p0, v1000, fine, tool0;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, z10, tool0;
        MoveL Offs(p0, 100, 100, 0), v100, fine, tool0;
        TPWrite "two legs fly-by: " + NumToStr(ClkRead(c), 2);
        ClkReset c;
        MoveL p0, v1000, fine, tool0;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, fine, tool0;
        MoveL Offs(p0, 100, 100, 0), v100, fine, tool0;
        TPWrite "two legs fine: " + NumToStr(ClkRead(c), 2);
    ENDPROC
ENDMODULE
