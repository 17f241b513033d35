MODULE opt_var_optional
    ! An optional VAR parameter: written only when it was passed.
    PROC compute(num x \VAR num square \VAR num cube)
        IF Present(square) square := x * x;
        IF Present(cube) cube := x * x * x;
    ENDPROC

    PROC main()
        VAR num sq := -1;
        VAR num cu := -1;
        compute 3 \square:=sq;
        TPWrite "sq=" \Num:=sq;
        TPWrite "cu=" \Num:=cu;
        compute 2 \cube:=cu;
        TPWrite "sq=" \Num:=sq;
        TPWrite "cu=" \Num:=cu;
        compute 4 \square:=sq \cube:=cu;
        TPWrite "sq=" \Num:=sq;
        TPWrite "cu=" \Num:=cu;
    ENDPROC
ENDMODULE
