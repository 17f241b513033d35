MODULE motion_unreachable
    ! A target two metres from an IRB 120 (reach 0.58 m): the controller stops with
    ! its motion error "50050 Position outside reach"; no ERROR handler takes it.
    CONST robtarget far := [[2300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    PROC main()
        TPWrite "moving";
        MoveJ far, v1000, fine, tool0;
        TPWrite "arrived";
    ERROR
        TPWrite "handled";
    ENDPROC
ENDMODULE
