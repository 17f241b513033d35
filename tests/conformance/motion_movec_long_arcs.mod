MODULE motion_movec_long_arcs
    ! Circles drawn with a pen pointing down all the way (start, circle point and end
    ! alike), in the default CirPathMode \PathFrame: a full circle as two half circles,
    ! then a 270° arc. The tool keeps its orientation ([0,0,1,0]) everywhere: the
    ! circle point's orientation picks the way the orientation goes round (a whole turn
    ! of axis 6 on the way is wrong). Every end is the programmed point.
    CONST robtarget centre := [[350, 0, 350], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR jointtarget j;

    PROC main()
        VAR robtarget here;
        ConfL \Off;
        MoveL Offs(centre, 0, -50, 0), v200, fine, tool0;
        MoveC Offs(centre, 50, 0, 0), Offs(centre, 0, 50, 0), v100, fine, tool0;
        show "first half";
        MoveC Offs(centre, -50, 0, 0), Offs(centre, 0, -50, 0), v100, fine, tool0;
        show "second half";
        MoveC Offs(centre, 35.3553, 35.3553, 0), Offs(centre, -50, 0, 0), v100, fine, tool0;
        show "270 degrees";
    ENDPROC

    PROC show(string what)
        VAR robtarget here;
        here := CRobT(\Tool:=tool0);
        TPWrite what + " at " + ValToStr(here.trans) + " " + ValToStr(here.rot);
    ENDPROC
ENDMODULE
