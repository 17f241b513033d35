MODULE fmt_math_functions
    ! FORMAT-DEPENDENT. Irrational results of math functions, 6 digits.
    PROC main()
        TPWrite "sin45=" \Num:=Sin(45);
        TPWrite "cos30=" \Num:=Cos(30);
        TPWrite "tan60=" \Num:=Tan(60);
        TPWrite "sqrt2=" \Num:=Sqrt(2);
        TPWrite "pow=" \Num:=Pow(2, 0.5);
        TPWrite "atan=" \Num:=ATan(0.5);
        TPWrite "e=" \Num:=Exp(1);
    ENDPROC
ENDMODULE
