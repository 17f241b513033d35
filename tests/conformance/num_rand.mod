MODULE num_rand
    ! Rand (RobotWare 6.15, manual 1.15) gives a num; ours lies in [0, 1) (docs/semantics.md).
    ! The values themselves are not checked, only their range and that they vary.
    PROC main()
        VAR num r;
        VAR num first;
        VAR bool varied := FALSE;
        VAR bool in_range := TRUE;
        first := Rand();
        FOR i FROM 1 TO 1000 DO
            r := Rand();
            IF r < 0 OR r >= 1 in_range := FALSE;
            IF r <> first varied := TRUE;
        ENDFOR
        TPWrite "in range " \Bool:=in_range;
        TPWrite "varied " \Bool:=varied;
    ENDPROC
ENDMODULE
