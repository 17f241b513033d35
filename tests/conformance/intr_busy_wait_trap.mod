MODULE intr_busy_wait_trap
    ! A loop that polls a flag without waiting: instructions take controller time, so
    ! the timer's trap comes (at 0.5 s) and sets the flag, and the loop ends.
    VAR intnum done_int;
    VAR bool done := FALSE;
    VAR clock c;

    TRAP set_done
        done := TRUE;
    ENDTRAP

    PROC main()
        CONNECT done_int WITH set_done;
        ITimer \Single, 0.5, done_int;
        ClkStart c;
        WHILE NOT done DO
        ENDWHILE
        TPWrite "flag seen, at least 0.5 s later " \Bool:=ClkRead(c) >= 0.5;
    ENDPROC
ENDMODULE
