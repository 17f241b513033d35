MODULE num_sqrt_pow_exp
    ! Sqrt, Pow, Exp (manual 1.15) on arguments with exact results.
    PROC main()
        TPWrite "sqrt16=" \Num:=Sqrt(16);
        TPWrite "sqrt225=" \Num:=Sqrt(2.25);
        TPWrite "sqrt0=" \Num:=Sqrt(0);
        TPWrite "pow210=" \Num:=Pow(2, 10);
        TPWrite "pow2m1=" \Num:=Pow(2, -1);
        TPWrite "pow103=" \Num:=Pow(10, 3);
        TPWrite "pow9h=" \Num:=Pow(9, 0.5);
        TPWrite "powm23=" \Num:=Pow(-2, 3);
        TPWrite "pow50=" \Num:=Pow(5, 0);
        TPWrite "exp0=" \Num:=Exp(0);
    ENDPROC
ENDMODULE
