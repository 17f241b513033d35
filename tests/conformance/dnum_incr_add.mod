MODULE dnum_incr_add
    ! Incr, Decr, Add and Clear take a num or a dnum (manual 1.15).
    PROC main()
        VAR dnum d := 10;
        Incr d;
        TPWrite "incr=" \Dnum:=d;
        Decr d;
        Decr d;
        TPWrite "decr=" \Dnum:=d;
        Add d, 5;
        TPWrite "add=" \Dnum:=d;
        Clear d;
        TPWrite "clear=" \Dnum:=d;
    ENDPROC
ENDMODULE
