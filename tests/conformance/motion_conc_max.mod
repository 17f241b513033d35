MODULE motion_conc_max
    ! Moves with \Conc: "the number of consecutive movement instructions is limited to
    ! 5" (the instruction manual). Six 10 mm moves at v100 given at once (each takes
    ! 0.1 s): the robot is still on the first when the sixth comes, which raises
    ! ERR_CONC_MAX. A move without \Conc (a stop point: the program waits for it) ends
    ! the row, and \Conc moves may be given again.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        FOR i FROM 1 TO 6 DO
            MoveL \Conc, Offs(p0, 10 * i, 0, 0), v100, z1, tool0;
            TPWrite "given " \Num:=i;
        ENDFOR
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_CONC_MAX TPWrite "ERR_CONC_MAX";
        MoveL p0, v100, fine, tool0;
        FOR i FROM 1 TO 5 DO
            MoveL \Conc, Offs(p0, 0, 10 * i, 0), v100, z1, tool0;
        ENDFOR
        MoveL p0, v100, fine, tool0;
        TPWrite "five again";
        RETURN;
    ENDPROC
ENDMODULE
