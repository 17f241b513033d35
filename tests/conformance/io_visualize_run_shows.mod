MODULE io_visualize_run_shows
    ! `rapid run` has no pendant screen: a \Visualize box is told on stderr when it
    ! opens and when it closes (header and message joined by " / "), while the
    ! TP output on stdout carries only what the program writes.
    VAR clock clk;

    PROC main()
        ClkStart clk;
        WaitUntil ClkRead(clk) >= 1 \Visualize \Header:="Waiting" \Message:="one second";
        TPWrite "done";
    ENDPROC
ENDMODULE
