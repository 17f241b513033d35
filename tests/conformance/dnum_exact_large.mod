MODULE dnum_exact_large
    ! dnum integers are exact up to 2^52 = 4503599627370496 (semantics 2.1).
    ! The big values are built by multiplication and only small results printed.
    PROC main()
        VAR dnum d;
        VAR dnum e;
        VAR dnum q;
        d := 65536;
        d := d * d;
        d := d * 1048576;
        ! d = 2^52, e = 4503599627370495
        e := d - 1;
        TPWrite "diff=" \Dnum:=d - e;
        TPWrite "last digit=" \Dnum:=e MOD 10;
        TPWrite "last three=" \Dnum:=e MOD 1000;
        q := 1000;
        q := q * q * q * q * q;
        ! q = 10^15
        TPWrite "lead=" \Dnum:=e DIV q;
        IF e + 1 = d TPWrite "round trip";
    ENDPROC
ENDMODULE
