MODULE motion_confl_circle
    ! ConfL\On checks where a circular move ends as it does a linear one (the manual's
    ! ConfL covers linear and circular moves): the circle's end says cf1 = 2 (axis 1 in
    ! 180..270 degrees), two quadrants from where the path keeps it (axis 1 near 0), so
    ! the MoveC itself stops the program; with ConfL\Off it arrives.
    CONST robtarget p0 := [[300, -50, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget via := [[350, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p1 := [[300, 50, 400], [0, 0, 1, 0], [2, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    PROC main()
        MoveJ p0, v1000, fine, tool0;
        ConfL \Off;
        MoveC via, p1, v500, fine, tool0;
        TPWrite "ConfL Off: arrived";
        MoveL p0, v500, fine, tool0;
        ConfL \On;
        MoveC via, p1, v500, fine, tool0;
        TPWrite "ConfL On: arrived";
    ENDPROC
ENDMODULE
