MODULE param_eval_order
    ! Arguments are evaluated before the routine body runs; IN arguments
    ! are values, not references.
    VAR num g := 1;

    PROC show(num a, num b)
        g := 100;
        TPWrite "a=" \Num:=a;
        TPWrite "b=" \Num:=b;
        TPWrite "g=" \Num:=g;
    ENDPROC

    PROC main()
        show g + 1, g * 5;
        TPWrite "g after=" \Num:=g;
    ENDPROC
ENDMODULE
