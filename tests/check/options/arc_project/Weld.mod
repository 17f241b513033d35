MODULE Weld
    ! One seam: start, weld, end, with the arc welding data of the Arc option.
    PERS seamdata seam1 := [0.5, 0.2, [1, 0, 22, 120, 0, 0, 0, 0, 0], 0, 0, 0, 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0, 0, [0, 0, 0, 0, 0, 0, 0, 0, 0], 0.5];
    PERS welddata weld1 := [8, 0, [1, 0, 22, 120, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 0, 0, 0, 0]];
    PERS weavedata weave1 := [1, 0, 3, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0];
    PERS tooldata torch := [TRUE, [[0, 0, 350], [1, 0, 0, 0]], [3, [0, 0, 120], [1, 0, 0, 0], 0, 0, 0]];
    CONST robtarget seam_start := [[400, -50, 300], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget seam_end := [[400, 50, 300], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        TPWrite "weld speed " \Num:=weld1.weld_speed;
        ArcLStart seam_start, v100, seam1, weld1, fine, torch;
        ArcLEnd seam_end, v100, seam1, weld1 \Weave:=weave1, fine, torch;
    ENDPROC
ENDMODULE
