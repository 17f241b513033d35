MODULE exit_from_handler
    ! EXIT in an ERROR handler stops execution for a serious error
    ! (manual 1.12: EXIT in the list of ways out of a handler).
    PROC main()
        VAR num zero := 0;
        VAR num x;
        x := 1 / zero;
        TPWrite "not reached";
    ERROR
        TPWrite "fatal, exiting";
        EXIT;
    ENDPROC
ENDMODULE
