MODULE motion_path_t_inpos
    ! \T (the move takes T seconds; manual: MoveL, argument T) and \Inpos
    ! (stoppointdata: a stop point of its own in place of the zone). Times from
    ! the timing model (docs/semantics.md, motion): IRB 120, TCP acceleration
    ! 10 m/s^2, fine-point settle 0.05 s.
    CONST jointtarget bent := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget straight := [[0, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR stoppointdata wait_half := [stoptime, TRUE, [0, 0, 0, 0], 0.5, 0, "", 0, 0];
    VAR stoppointdata settle_long := [inpos, TRUE, [50, 50, 0.3, 2], 0, 0, "", 0, 0];
    VAR clock c;

    PROC main()
        ! 100 mm in 2 s instead of at v100: the move's speed is chosen so that
        ! 100/v + v/10000 = 2 (v = 50.1 mm/s); with the settle 2.05 s.
        MoveJ p0, v1000, fine, tool0;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100 \T:=2, fine, tool0;
        TPWrite "MoveL \\T:=2: " + NumToStr(ClkRead(c), 2);
        ! A joint move takes its time too: axis 5 by 30 deg in 1 s, 1.05 s.
        MoveAbsJ straight, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveAbsJ bent, v1000 \T:=1, fine, tool0;
        TPWrite "MoveAbsJ \\T:=1: " + NumToStr(ClkRead(c), 2);
        ! stoptime1_0 (progsynch FALSE): the program goes on when the robot stands at
        ! the point, 100/100 + 100/10000 = 1.01 s, though the zone is z50; the robot
        ! stands 1 s there, done at 2.01 s.
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, z50 \Inpos:=stoptime1_0, tool0;
        TPWrite "stoptime1_0, program on after " + NumToStr(ClkRead(c), 2);
        WaitRob \InPos;
        TPWrite "stoptime1_0, done after " + NumToStr(ClkRead(c), 2);
        ! progsynch TRUE: the program waits for the stop time, 1.01 + 0.5 s.
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, z50 \Inpos:=wait_half, tool0;
        TPWrite "stop time 0.5, synchronized: " + NumToStr(ClkRead(c), 2);
        ! inpos100: in position after the fine settle (mintime 0, maxtime 2),
        ! 1.06 s; a mintime of 0.3 s holds it longer, 1.31 s.
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, z10 \Inpos:=inpos100, tool0;
        WaitRob \InPos;
        TPWrite "inpos100: " + NumToStr(ClkRead(c), 2);
        MoveL p0, v1000, fine, tool0;
        ClkReset c;
        ClkStart c;
        MoveL Offs(p0, 100, 0, 0), v100, z10 \Inpos:=settle_long, tool0;
        TPWrite "mintime 0.3: " + NumToStr(ClkRead(c), 2);
    ENDPROC
ENDMODULE
