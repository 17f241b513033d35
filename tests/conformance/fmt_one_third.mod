MODULE fmt_one_third
    ! FORMAT-DEPENDENT. num values print with 6 significant digits
    ! (semantics 2.2, "%.6G"-like); num is a single, 1/3 = 0.333333343...
    PROC main()
        TPWrite "a=" \Num:=1 / 3;
        TPWrite "b=" \Num:=2 / 3;
        TPWrite "c=" \Num:=10 / 3;
        TPWrite "d=" \Num:=100 / 7;
        TPWrite "e=" \Num:=-1 / 3;
        TPWrite "f=" \Num:=1 / 7;
        TPWrite "g=" \Num:=1000 / 3;
    ENDPROC
ENDMODULE
