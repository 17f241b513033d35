MODULE motion_ori_corner
    ! Reorientation without TCP movement (§2.2.3): the zone is an angle (zone_ori),
    ! and no corner joins such a move to a move of the TCP. IRB 120 with tool0 at
    ! axis 5 = 30 deg: turning the tool about its z axis turns axis 6 alone, at
    ! v_ori 500 deg/s capped by axis 6's 420 deg/s, with the reorientation
    ! acceleration of 2000 deg/s^2; a stop point settles 0.05 s.
    CONST jointtarget bent := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget p0;
    VAR robtarget p30;
    VAR robtarget p60;
    VAR clock c;
    VAR num flown;

    PROC main()
        MoveAbsJ bent, v1000, fine, tool0;
        p0 := CRobT(\Tool:=tool0);
        p30 := p0;
        p30.rot := p0.rot * OrientZYX(30, 0, 0);
        p60 := p0;
        p60.rot := p0.rot * OrientZYX(60, 0, 0);
        ! Two turns of 30 deg, each a triangle 2*sqrt(30/2000) = 0.2449 s and a
        ! 0.05 s settle: 0.59 s.
        ClkStart c;
        MoveL p30, v1000, fine, tool0;
        MoveL p60, v1000, fine, tool0;
        TPWrite "two stop points: " + NumToStr(ClkRead(c), 2);
        ! The same turns with z50 at 30 deg (zone_ori 7.5 deg): up to 300 deg/s over
        ! 22.5 deg (0.15 s), the corner from 22.5 to 37.5 deg at 300 deg/s (0.05 s),
        ! down over 22.5 deg (0.15 s): 0.35 s, plus 0.05 s settle = 0.40 s.
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL p30, v1000, z50, tool0;
        MoveL p60, v1000, fine, tool0;
        TPWrite "one corner: " + NumToStr(ClkRead(c), 2);
        ! From p60 back to p0 and on down 50 mm: no corner joins the turn to the move
        ! of the TCP, so with z50 at p0 the robot stops there as with fine, only
        ! without the 0.05 s settle.
        ClkReset c;
        ClkStart c;
        MoveL p0, v1000, z50, tool0;
        MoveL Offs(p0, 0, 0, -50), v1000, fine, tool0;
        flown := ClkRead(c);
        MoveL p60, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL p0, v1000, fine, tool0;
        MoveL Offs(p0, 0, 0, -50), v1000, fine, tool0;
        TPWrite "fine minus z50 before a TCP move: " + NumToStr(ClkRead(c) - flown, 2);
    ENDPROC
ENDMODULE
