MODULE motion_path_fllwtime
    ! A follow-time stop point (stoppointdata type fllwtime) follows a conveyor
    ! object; on a move in no conveyor's work object it stops the program, naming it.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        TPWrite "before";
        MoveL Offs(p0, 100, 0, 0), v100, fine \Inpos:=fllwtime1_0, tool0;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
