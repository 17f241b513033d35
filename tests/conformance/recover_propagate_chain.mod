MODULE recover_propagate_chain
    ! An error in a routine without handler is raised again at the call in
    ! the caller, up to the first routine with a handler (manual 1.12).
    VAR num zero := 0;

    PROC c3()
        VAR num x;
        TPWrite "c3 start";
        x := 1 / zero;
        TPWrite "c3 end";
    ENDPROC

    PROC c2()
        TPWrite "c2 start";
        c3;
        TPWrite "c2 end";
    ENDPROC

    PROC c1()
        TPWrite "c1 start";
        c2;
        TPWrite "c1 end";
    ERROR
        TPWrite "c1 handler";
        TRYNEXT;
    ENDPROC

    PROC main()
        c1;
        TPWrite "main end";
    ENDPROC
ENDMODULE
