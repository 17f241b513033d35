MODULE literal_mixed_arith_unstreamed
    ! Run with --virtual-io, which once compiled every body without the checker's
    ! facts; it is streamed now like any load, and must still agree.
    ! A literal takes the type of the other operand, and num + dnum is a dnum,
    ! as is dnum DIV num (manual §1.3.5, arithmetic table). So in n + d + 0.1 the
    ! 0.1 is a dnum: 2 + 0.1 in double precision prints 2.1000000000 with 10
    ! decimals (as a single-precision 0.1 widened, 0.100000001490116…, it would
    ! print 2.1000000015). In d DIV 1 + 0.1 = 1.1 both literals are dnums, so
    ! the sum is the double nearest 1.1 and equals it (as singles widened, 1 +
    ! 0.100000001490116… is not 1.10000002384185…, the single nearest 1.1).
    PROC main()
        VAR num n := 1;
        VAR dnum d := 1;
        VAR dnum r;
        r := n + d + 0.1;
        TPWrite "r=" + DnumToStr(r, 10);
        TPWrite "eq=" \Bool:=d DIV 1 + 0.1 = 1.1;
    ENDPROC
ENDMODULE
