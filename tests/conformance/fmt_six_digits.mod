MODULE fmt_six_digits
    ! FORMAT-DEPENDENT. Rounding to 6 significant digits (semantics 2.2:
    ! 1.141367 -> "1.14137", 23 -> "23").
    PROC main()
        TPWrite "a=" \Num:=1.141367;
        TPWrite "b=" \Num:=12345.67;
        TPWrite "c=" \Num:=3.14159265;
        TPWrite "d=" \Num:=pi;
        TPWrite "e=" \Num:=0.1234567;
        TPWrite "f=" \Num:=98765.4321;
        TPWrite "g=" \Num:=23;
        TPWrite "h=" \Num:=0.5 + 1 / 3;
        TPWrite "i=" \Num:=2 / 3 * 3;
    ENDPROC
ENDMODULE
