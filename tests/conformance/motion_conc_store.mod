MODULE motion_conc_store
    ! A move with \Conc is not allowed between StorePath and RestoPath (the instruction
    ! manual): execution stops there, naming it.
    CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveJ p0, v1000, fine, tool0;
        StorePath;
        TPWrite "stored";
        MoveL \Conc, Offs(p0, 0, 0, 10), v100, fine, tool0;
        TPWrite "not reached";
        RestoPath;
    ENDPROC
ENDMODULE
