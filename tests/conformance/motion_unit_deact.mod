MODULE motion_unit_deact
    ! DeactUnit of a TCP robot (manual: DeactUnit): a TCP robot cannot be
    ! deactivated; execution stops.
    PROC main()
        TPWrite "before";
        DeactUnit ROB_1;
        TPWrite "not reached";
    ENDPROC
ENDMODULE
