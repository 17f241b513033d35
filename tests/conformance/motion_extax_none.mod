MODULE motion_extax_none
    ! A program run alone has no external axes and no conveyors. MoveExtJ then moves
    ! nothing: a stop point of no length, which stands the 0.05 s settle time; values
    ! for axes the system does not have are ignored, and read back as 9E9. A work
    ! object on a conveyor the system does not have is ERR_CNV_NOT_ACT (1152).
    PERS wobjdata wobj_cnv1 := [FALSE, FALSE, "CNV1", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];
    VAR clock c;
    VAR jointtarget jt;

    PROC main()
        ClkStart c;
        MoveExtJ [[0,0,0,0,0,0],[100,9E9,9E9,9E9,9E9,9E9]], v1000, fine;
        TPWrite "t " \Num:=ClkRead(c);
        jt := CJointT();
        TPWrite "eax_a " \Num:=jt.extax.eax_a;
        WaitWObj wobj_cnv1;
        TPWrite "not reached";
    ERROR
        TPWrite "error " \Num:=ERRNO;
        TPWrite "ERR_CNV_NOT_ACT " \Bool:=ERRNO = ERR_CNV_NOT_ACT;
        RETURN;
    ENDPROC
ENDMODULE
