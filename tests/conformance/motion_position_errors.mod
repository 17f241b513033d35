MODULE motion_position_errors
    ! A position function that must turn or move a frame cannot use an orientation of
    ! length 0. uncertain (rapid-vm builtins/motion/frame.rs): the controller stops
    ! with an orientation event when such a target is used in a move; the functions
    ! raise ERR_ARGVALERR here. Offs needs no orientation and accepts it.
    VAR robtarget bad := [[1, 2, 3], [0, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget good := [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR wobjdata broken := [FALSE, TRUE, "", [[0, 0, 0], [0, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
    VAR wobjdata floor := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];

    PROC try(num which)
        VAR robtarget r;
        TEST which
        CASE 1:
            r := RelTool(bad, 0, 0, 10);
        CASE 2:
            r := MirPos(bad, floor);
        CASE 3:
            r := MirPos(good, broken);
        CASE 4:
            PDispSet [[0, 0, 0], [0, 0, 0, 0]];
        CASE 5:
            r := Offs(bad, 1, 1, 1);
        ENDTEST
        TPWrite "case " + ValToStr(which) + " ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "case " + ValToStr(which) + " ERR_ARGVALERR";
        RETURN;
    ENDPROC

    PROC main()
        FOR i FROM 1 TO 5 DO
            try i;
        ENDFOR
        ! The failed PDispSet left no displacement.
        TPWrite "pdisp " + ValToStr(C_PROGDISP.pdisp);
    ENDPROC
ENDMODULE
