MODULE fmt_dnum
    ! FORMAT-DEPENDENT. \Dnum prints about 15 significant digits (semantics
    ! 2.2, "(?)"); assumed: %.15G with the same exponent rules.
    PROC main()
        VAR dnum one := 1;
        VAR dnum d;
        TPWrite "a=" \Dnum:=one / 3;
        TPWrite "b=" \Dnum:=2 * one / 3;
        TPWrite "c=" \Dnum:=one / 10;
        d := 1000000;
        d := d * d;
        TPWrite "d=" \Dnum:=d;
        d := 123456789;
        TPWrite "e=" \Dnum:=d;
        d := 65536;
        d := d * d * 1048576;
        TPWrite "f=" \Dnum:=d;
    ENDPROC
ENDMODULE
