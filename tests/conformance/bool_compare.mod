MODULE bool_compare
    ! = and <> work on bool values (manual 1.3.1: any value type).
    PROC main()
        VAR bool t := TRUE;
        VAR bool f := FALSE;
        TPWrite "a=" \Bool:=t = TRUE;
        TPWrite "b=" \Bool:=t <> f;
        TPWrite "c=" \Bool:=(1 < 2) = (3 < 4);
        TPWrite "d=" \Bool:=f = (1 > 2);
        ! <> on bool is the same as XOR
        TPWrite "e=" \Bool:=(t <> t) = (t XOR t);
    ENDPROC
ENDMODULE
