MODULE return_from_main
    ! RETURN in main ends main, and with it the program, normally
    ! (manual 1.1.5, routine termination).
    PROC main()
        VAR num x := 1;
        TPWrite "start";
        IF x = 1 RETURN;
        TPWrite "not reached";
        x := 2;
    ENDPROC
ENDMODULE
