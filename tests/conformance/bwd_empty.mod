MODULE bwd_empty
    ! An empty BACKWARD handler (manual 1.21: such a procedure is a no-op
    ! when stepped backwards); forward it runs normally.
    PROC tick(INOUT num n)
        n := n + 1;
    BACKWARD
    ENDPROC

    PROC main()
        VAR num n := 0;
        tick n;
        tick n;
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
