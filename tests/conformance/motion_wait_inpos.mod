MODULE motion_wait_inpos
    ! Manual 2.3: WaitTime \InPos and WaitUntil \InPos end a sequence of logic run
    ! ahead of the robot: the robot first stands at the end of its last move (its
    ! fly-by point becomes a stop point, without a fine point's settle), then the wait
    ! counts. 100 mm at v100 with the IRB 120's 10 m/s² path acceleration take
    ! 100/100 + 100/10000 = 1.01 s; WaitTime \InPos, 0.5 ends 0.5 s later; WaitUntil
    ! \InPos with a condition already TRUE ends when the robot stands.
    VAR clock c;

    PROC main()
        ConfL \Off;
        ClkStart c;
        MoveL [[374,0,530],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, z50, tool0;
        WaitTime \InPos, 0.5;
        TPWrite "waited " \Num:=ClkRead(c);
        ClkReset c;
        ClkStart c;
        MoveL [[374,0,630],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, z50, tool0;
        WaitUntil \InPos, TRUE;
        TPWrite "until " \Num:=ClkRead(c);
    ENDPROC
ENDMODULE
