MODULE Logger
    PROC log_main()
        ! Background task: reports the cycle counter.
        WHILE TRUE DO
            WaitTime 5;
        ENDWHILE
    ENDPROC
ENDMODULE
