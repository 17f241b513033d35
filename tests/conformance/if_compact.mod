MODULE if_compact
    ! Compact IF runs one simple statement when the condition holds (manual 1.5).
    PROC main()
        VAR num a := 1;
        VAR num b := 0;
        IF a > 0 TPWrite "compact call";
        IF a > 0 b := 10;
        IF a < 0 b := 20;
        IF a = 1 GOTO skip;
        TPWrite "not printed";
        skip:
        TPWrite "b=" \Num:=b;
        IF b = 10 Incr b;
        TPWrite "b=" \Num:=b;
    ENDPROC
ENDMODULE
