MODULE motion_frames_errors
    ! Points that define no frame (on one line, or two of them in one place) raise
    ! ERR_FRAME in DefFrame, DefDFrame and DefAccFrame (their pages: "the frame cannot
    ! be calculated"). uncertain (rapid-vm builtins/motion/fit.rs): a DefFrame \Origin
    ! other than 1..3, and a DefAccFrame TargetsInList outside 3..10 or larger than
    ! the lists, raise ERR_ARGVALERR.
    VAR robtarget t := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR robtarget one{4};
    VAR robtarget two{4};
    VAR num max_err := -1;
    VAR num mean_err := -1;

    FUNC robtarget at(num x, num y, num z)
        RETURN Offs(t, x, y, z);
    ENDFUNC

    PROC report(string what)
        IF ERRNO = ERR_FRAME THEN
            TPWrite what + " ERR_FRAME";
        ELSEIF ERRNO = ERR_ARGVALERR THEN
            TPWrite what + " ERR_ARGVALERR";
        ELSE
            TPWrite what + " other error";
        ENDIF
    ENDPROC

    PROC try_frame(robtarget p1, robtarget p2, robtarget p3, num origin)
        VAR pose f;
        f := DefFrame(p1, p2, p3 \Origin:=origin);
        TPWrite "DefFrame ok";
    ERROR
        report "DefFrame";
        RETURN;
    ENDPROC

    PROC try_dframe(robtarget o3, robtarget n3)
        VAR pose f;
        f := DefDFrame(at(0, 0, 0), at(100, 0, 0), o3, at(0, 0, 0), at(100, 0, 0), n3);
        TPWrite "DefDFrame ok";
    ERROR
        report "DefDFrame";
        RETURN;
    ENDPROC

    PROC try_acc(num n)
        VAR pose f;
        f := DefAccFrame(one, two, n, max_err, mean_err);
        TPWrite "DefAccFrame ok";
    ERROR
        report "DefAccFrame";
        RETURN;
    ENDPROC

    PROC main()
        ! The third point on the line through the first two.
        try_frame at(0, 0, 0), at(100, 0, 0), at(250, 0, 0), 1;
        ! The first two in one place.
        try_frame at(10, 10, 10), at(10, 10, 10), at(0, 50, 0), 1;
        try_frame at(0, 0, 0), at(100, 0, 0), at(0, 50, 0), 4;
        try_frame at(0, 0, 0), at(100, 0, 0), at(0, 50, 0), 3;
        try_dframe at(50, 0, 0), at(0, 100, 0);
        try_dframe at(0, 100, 0), at(-30, 0, 0);
        try_dframe at(0, 100, 0), at(0, 100, 0);
        ! Four points on the x axis.
        one{1} := at(0, 0, 0);
        one{2} := at(100, 0, 0);
        one{3} := at(200, 0, 0);
        one{4} := at(300, 0, 0);
        two := one;
        try_acc 4;
        one{4} := at(0, 100, 0);
        two := one;
        try_acc 2;
        try_acc 11;
        try_acc 5;
        try_acc 3.5;
        ! A failed call writes no errors.
        TPWrite "errors untouched " \Bool:=(max_err = -1 AND mean_err = -1);
        try_acc 4;
        TPWrite "errors " \Num:=Round(max_err + mean_err \Dec:=3);
    ENDPROC
ENDMODULE
