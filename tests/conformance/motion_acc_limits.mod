MODULE motion_acc_limits
    ! PathAccLim and WorldAccLim bound the TCP's acceleration and braking on a linear
    ! path. Worked by hand for a 100 mm MoveL at v500 to a fine point (IRB 120: path
    ! acceleration 10 m/s²; 0.05 s settle; ClkRead in ms):
    !  - no limit: 100/500 + 500/10000 = 0.25 s, + 0.05 = 0.300;
    !  - AccMax 2 m/s²: up 0.25 s over 62.5 mm, down 0.05 s over 12.5 mm, 25 mm at
    !    500 mm/s in 0.05 s: 0.35 s, + 0.05 = 0.400;
    !  - AccMax and DecelMax 2 m/s²: 62.5 + 62.5 > 100 mm, a triangle to
    !    √(2000 · 100) = 447.2 mm/s: 2 · 0.2236 s = 0.4472 s, + 0.05 = 0.497;
    !  - WorldAccLim 1 m/s² (both ways): √(1000 · 100) = 316.2 mm/s, 0.6325 s,
    !    + 0.05 = 0.682.
    CONST robtarget pA := [[300,-50,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pB := [[300,50,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR clock c;

    PROC main()
        ConfL \Off;
        MoveJ pA, v1000, fine, tool0;
        Timed pB, "no limit";
        PathAccLim TRUE \AccMax:=2, FALSE;
        TPWrite "acclim " \Bool:=C_MOTSET.acclim;
        TPWrite "accmax " \Num:=C_MOTSET.accmax;
        Timed pA, "acc 2";
        PathAccLim TRUE \AccMax:=2, TRUE \DecelMax:=2;
        Timed pB, "acc and decel 2";
        PathAccLim FALSE, FALSE;
        WorldAccLim \On:=1;
        TPWrite "worldaccmax " \Num:=C_MOTSET.worldaccmax;
        Timed pA, "world 1";
        WorldAccLim \Off;
        Timed pB, "no limit again";
        PathAccLim TRUE, FALSE;
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "ERR_ARGVALERR";
            TRYNEXT;
        ENDIF
    ENDPROC

    PROC Timed(robtarget target, string what)
        ClkReset c;
        ClkStart c;
        MoveL target, v500, fine, tool0;
        ClkStop c;
        TPWrite what + " " \Num:=ClkRead(c);
    ENDPROC
ENDMODULE
