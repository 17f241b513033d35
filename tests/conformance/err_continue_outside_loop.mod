MODULE err_continue_outside_loop
    ! Continue belongs in a FOR or WHILE loop (manual 1.5); elsewhere the program is
    ! refused when it is loaded.
    PROC main()
        TPWrite "not run";
        Continue;
    ENDPROC
ENDMODULE
