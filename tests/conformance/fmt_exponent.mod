MODULE fmt_exponent
    ! FORMAT-DEPENDENT. Exponent form as in %G: used when the decimal
    ! exponent is < -4 or >= 6; uppercase E, sign, at least two exponent
    ! digits (semantics 2.2; 9E9 prints as 9E+09 like in saved modules).
    PROC main()
        VAR num big := 1E10;
        VAR num unused := 9E9;
        TPWrite "a=" \Num:=big;
        TPWrite "b=" \Num:=unused;
        TPWrite "c=" \Num:=1234567;
        TPWrite "d=" \Num:=123456;
        TPWrite "e=" \Num:=1000000;
        TPWrite "f=" \Num:=999999;
        TPWrite "g=" \Num:=0.00001;
        TPWrite "h=" \Num:=0.0001;
        TPWrite "i=" \Num:=2.5E-5;
        TPWrite "j=" \Num:=1.5E20;
    ENDPROC
ENDMODULE
