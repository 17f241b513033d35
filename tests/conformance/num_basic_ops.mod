MODULE num_basic_ops
    ! The four num operators and unary minus (manual 1.3.1, arithmetic table).
    PROC main()
        VAR num a := 7;
        VAR num b := 2;
        TPWrite "add=" \Num:=a + b;
        TPWrite "sub=" \Num:=a - b;
        TPWrite "mul=" \Num:=a * b;
        TPWrite "div=" \Num:=a / b;
        TPWrite "neg=" \Num:=-a;
        TPWrite "sub2=" \Num:=b - a;
        TPWrite "zero=" \Num:=a - a;
    ENDPROC
ENDMODULE
