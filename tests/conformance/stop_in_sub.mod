MODULE stop_in_sub
    ! Stop inside a called routine halts everything.
    PROC halt(num v)
        IF v > 1 Stop;
        TPWrite "v=" \Num:=v;
    ENDPROC

    PROC main()
        halt 1;
        halt 2;
        halt 3;
    ENDPROC
ENDMODULE
