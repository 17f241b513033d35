MODULE motion_confl
    ! ConfL\On: a linear move to a robtarget whose programmed configuration the path
    ! cannot end in stops the program; ConfL\Off follows the path's configuration.
    ! From p0 (axis 1 near 0, quadrant 0) a 100 mm move keeps cf1 = 0; the target says
    ! cf1 = 2 (axis 1 in 180..270 degrees), two quadrants away.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p1 := [[400, 0, 400], [0, 0, 1, 0], [2, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    PROC main()
        MoveJ p0, v1000, fine, tool0;
        ConfL \Off;
        MoveL p1, v500, fine, tool0;
        TPWrite "ConfL Off: arrived";
        MoveL p0, v500, fine, tool0;
        ConfL \On;
        MoveL p1, v500, fine, tool0;
        TPWrite "ConfL On: arrived";
    ENDPROC
ENDMODULE
