MODULE num_trig
    ! Trigonometric functions work in degrees (semantics 3.2); the tiny
    ! rounding errors of Sin(30) etc. vanish in the 6-digit print format.
    PROC main()
        TPWrite "sin30=" \Num:=Sin(30);
        TPWrite "cos60=" \Num:=Cos(60);
        TPWrite "sin90=" \Num:=Sin(90);
        TPWrite "cos0=" \Num:=Cos(0);
        TPWrite "tan45=" \Num:=Tan(45);
        TPWrite "sinm90=" \Num:=Sin(-90);
        TPWrite "atan1=" \Num:=ATan(1);
        TPWrite "atan2a=" \Num:=ATan2(1, 1);
        TPWrite "atan2b=" \Num:=ATan2(1, -1);
        TPWrite "atan2c=" \Num:=ATan2(-1, -1);
        TPWrite "asin=" \Num:=ASin(0.5);
        TPWrite "asin1=" \Num:=ASin(1);
        TPWrite "acos0=" \Num:=ACos(0);
        TPWrite "acosm1=" \Num:=ACos(-1);
    ENDPROC
ENDMODULE
