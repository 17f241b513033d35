MODULE exit_basic
    ! EXIT ends program execution (manual 1.5); nothing after it runs and the
    ! run ends normally (exit status 0).
    PROC main()
        VAR num n := 0;
        TPWrite "before";
        n := n + 1;
        EXIT;
        TPWrite "after";
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
