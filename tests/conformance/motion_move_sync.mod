MODULE motion_move_sync
    ! MoveLSync runs a procedure where the robot passes its point. Worked by hand
    ! (IRB 120, 10 m/s² path acceleration, 0.05 s settle at fine points):
    !  - 100 mm at v100 to a fine point: the robot stands there after
    !    100/100 + 100/10000 = 1.01 s: "arrived at 1.01"; the program goes on after
    !    the settle time: "after the move 1.06";
    !  - 100 mm at v100 to a z10 fly-by point, then a right angle: the corner starts
    !    10 mm before the point, 0.01 + 89.5/100 = 0.905 s after the move starts at
    !    1.06, and takes 2 · 10/100 = 0.2 s at constant speed: its middle is at
    !    1.965 + 0.1 = 2.065: "passed at 2.065";
    !  - a name that is no procedure: ERR_REFUNKPRC.
    CONST robtarget p0 := [[300,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR clock c;

    PROC main()
        ConfL \Off;
        MoveL p0, v500, fine, tool0;
        ClkStart c;
        MoveLSync Offs(p0, 0, 100, 0), v100, fine, tool0, "Arrived";
        TPWrite "after the move " \Num:=ClkRead(c);
        MoveLSync Offs(p0, 0, 200, 0), v100, z10, tool0, "Passed";
        MoveL Offs(p0, 100, 200, 0), v100, fine, tool0;
        TPWrite "done";
        MoveLSync p0, v100, fine, tool0, "NoSuch";
    ERROR
        IF ERRNO = ERR_REFUNKPRC THEN
            TPWrite "ERR_REFUNKPRC";
            RETURN;
        ENDIF
    ENDPROC

    PROC Arrived()
        TPWrite "arrived at " \Num:=ClkRead(c);
    ENDPROC

    PROC Passed()
        TPWrite "passed at " \Num:=ClkRead(c);
    ENDPROC
ENDMODULE
