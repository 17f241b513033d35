MODULE motion_calib_errors
    ! The calibration built-ins' error paths (manual 1.18). Positions that define no
    ! axis frame are ERR_FRAME; a wrong count or a tool of the wrong kind (a
    ! stationary tool for MToolTCPCalib) ERR_ARGVALERR. Approach positions that fix
    ! no TCP stop execution: the manual documents no error to catch for them.
    PERS tooldata held := [TRUE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 0], [1, 0, 0, 0], 0, 0, 0]];
    PERS tooldata fixed := [FALSE, [[0, 0, 0], [1, 0, 0, 0]], [1, [0, 0, 0], [1, 0, 0, 0], 0, 0, 0]];
    CONST jointtarget home := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR num stage := 0;

    PROC main()
        VAR num maxerr;
        VAR num meanerr;
        VAR robtarget pts{4};
        VAR pose axis;
        ! Four points on one line.
        FOR i FROM 1 TO 4 DO
            pts{i} := [[100 * i, 0, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
        ENDFOR
        stage := 1;
        axis := CalcRotAxisFrame(ROB_1, pts, 4, maxerr, meanerr);
        stage := 2;
        axis := CalcRotAxisFrame(ROB_1, pts, 3, maxerr, meanerr);
        stage := 3;
        axis := CalcRotAxisFrame(ROB_1, pts, 5, maxerr, meanerr);
        ! On a circle, but the positive z point lies in the circle's plane.
        pts{2}.trans := [0, 100, 300];
        pts{3}.trans := [-100, 0, 300];
        pts{4}.trans := [0, -100, 300];
        stage := 4;
        axis := CalcRotAxFrameZ(pts, 4, [[50, 50, 300], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], maxerr, meanerr);
        stage := 5;
        MToolTCPCalib home, home, home, home, fixed, maxerr, meanerr;
        TPWrite "the same position four times:";
        stage := 6;
        MToolTCPCalib home, home, home, home, held, maxerr, meanerr;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FRAME THEN
            TPWrite "stage " + NumToStr(stage, 0) + ": ERR_FRAME";
            TRYNEXT;
        ELSEIF ERRNO = ERR_ARGVALERR THEN
            TPWrite "stage " + NumToStr(stage, 0) + ": ERR_ARGVALERR";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
