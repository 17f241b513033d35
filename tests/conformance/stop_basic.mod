MODULE stop_basic
    ! Stop stops program execution (manual 1.5); in `rapid run` the run ends
    ! there with status 0 and nothing after it runs.
    PROC main()
        VAR num n := 1;
        TPWrite "before stop";
        Stop;
        n := 2;
        TPWrite "after stop";
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
