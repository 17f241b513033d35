MODULE alias_arith_base_type_unstreamed
    ! Run with --virtual-io, which once compiled every body without the checker's
    ! facts; it is streamed now like any load, and must still agree.
    ! Manual §1.3.5, footnote ii of the arithmetic table: when an operand has an
    ! alias data type, the result has the alias's base type (num, dnum or pos).
    ! So distance * 2 is a num, -d1 too, while d1 itself stays a distance.
    ALIAS num distance;
    VAR distance d1 := 250;

    PROC main()
        VAR distance d2 := 4;
        TPWrite "d1: " + Type(d1);
        TPWrite "d1*2: " + Type(d1 * 2);
        TPWrite "d2+d1: " + Type(d2 + d1);
        TPWrite "-d2: " + Type(-d2);
        TPWrite "value: " \Num:=d1 * 2 + d2;
    ENDPROC
ENDMODULE
