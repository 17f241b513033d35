MODULE clock_virtual_time
    ! Clocks count controller time (§1.14); WaitTime advances it (virtual time:
    ! no real waiting). ClkRead gives whole milliseconds.
    VAR clock c;
    PROC main()
        ClkReset c;
        TPWrite "reset " \Num:=ClkRead(c);
        ClkStart c;
        WaitTime 1.5;
        TPWrite "running " \Num:=ClkRead(c);
        ClkStop c;
        WaitTime 2;
        TPWrite "stopped " \Num:=ClkRead(c);
        ClkStart c;
        WaitTime 0.25;
        ClkStop c;
        TPWrite "again " \Num:=ClkRead(c);
        ClkReset c;
        TPWrite "reset " \Num:=ClkRead(c);
    ENDPROC
ENDMODULE
