MODULE recover_return_proc
    ! RETURN in a PROC's handler leaves the routine; the caller goes on.
    PROC risky(num d)
        VAR num x;
        TPWrite "risky start";
        x := 1 / d;
        TPWrite "risky end";
    ERROR
        TPWrite "risky handler";
        RETURN;
    ENDPROC

    PROC main()
        risky 0;
        TPWrite "main continues";
        risky 1;
    ENDPROC
ENDMODULE
