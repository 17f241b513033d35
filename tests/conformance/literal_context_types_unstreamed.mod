MODULE literal_context_types_unstreamed
    ! Run with --virtual-io, which once compiled every body without the checker's
    ! facts; it is streamed now like any load, and must still agree.
    ! A numeric literal takes its type from its context, and so does arithmetic
    ! of literals only: RAPID accepts `VAR dnum d := 4294967295;`, a value no num
    ! holds exactly. In `VAR dnum x := 2 * 0.1;` both literals are dnum and the
    ! product is computed in double precision: 0.1 as a double is
    ! 0.1000000000000000055…, doubled exactly 0.2000000000000000111…, the
    ! double nearest 0.2. Computed in single precision and widened it would be
    ! 0.20000000298023223876953125 (0.1 as a float is 0.100000001490116…), which
    ! prints 0.2000000030 with 10 decimals and 0.200000002980232 with \Dnum.
    VAR dnum m := 2 * 0.1;

    PROC main()
        VAR dnum x := 2 * 0.1;
        VAR dnum y;
        TPWrite "x=" \Dnum:=x;
        TPWrite "x10=" + DnumToStr(x, 10);
        y := -(7 - 0.1 * 3);
        TPWrite "y10=" + DnumToStr(y, 10);
        TPWrite "m10=" + DnumToStr(m, 10);
    ENDPROC
ENDMODULE
