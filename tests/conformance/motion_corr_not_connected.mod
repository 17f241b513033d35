MODULE motion_corr_not_connected
    ! A corrdescr whose generator was disconnected names none: CorrWrite to it stops
    ! execution (the manual names no error an ERROR handler could take; corr.rs,
    ! uncertain). The first write and read work.
    VAR corrdescr a;
    PROC main()
        CorrCon a;
        CorrWrite a, [1, 0, 0];
        TPWrite "connected " \Pos:=CorrRead();
        CorrDiscon a;
        TPWrite "disconnected " \Pos:=CorrRead();
        CorrWrite a, [1, 0, 0];
        TPWrite "not reached";
    ENDPROC
ENDMODULE
