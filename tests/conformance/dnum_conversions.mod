MODULE dnum_conversions
    ! NumToDnum always succeeds; DnumToNum converts a value that fits
    ! (manual 1.19, semantics 2.1).
    PROC main()
        VAR num n := 42;
        VAR dnum d;
        d := NumToDnum(n);
        TPWrite "d=" \Dnum:=d;
        d := d * 1000;
        TPWrite "d2=" \Dnum:=d;
        n := DnumToNum(d);
        TPWrite "n=" \Num:=n;
        n := DnumToNum(d \Integer);
        TPWrite "n2=" \Num:=n / 1000;
        d := NumToDnum(2.5) * 2;
        TPWrite "d3=" \Dnum:=d;
    ENDPROC
ENDMODULE
