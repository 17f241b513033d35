MODULE fmt_snap
    ! FORMAT-DEPENDENT. A value whose fractional part is below 0.000005 or
    ! above 0.999995 is rounded and shown as an integer (semantics 2.2), so
    ! Cos(90) (about -4E-08 in single precision) prints 0, not an exponent
    ! form, and never "-0".
    PROC main()
        TPWrite "a=" \Num:=Cos(90);
        TPWrite "b=" \Num:=Sin(180);
        TPWrite "c=" \Num:=0.000001;
        TPWrite "d=" \Num:=0.000003;
        TPWrite "e=" \Num:=4.999999;
        TPWrite "f=" \Num:=1.000003;
        TPWrite "g=" \Num:=12.000003;
    ENDPROC
ENDMODULE
