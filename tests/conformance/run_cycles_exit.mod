MODULE run_cycles_exit
    ! Continuous run mode (`--cycles 5`): the end of main starts the next cycle, but
    ! EXIT ends execution where a restart is not allowed (§1.12), so the third cycle's
    ! EXIT ends the run after three cycles, not five. The run ends without an error.
    VAR num cycle := 0;

    PROC main()
        cycle := cycle + 1;
        TPWrite "cycle " \Num:=cycle;
        IF cycle = 3 EXIT;
        TPWrite "end of main";
    ENDPROC
ENDMODULE
