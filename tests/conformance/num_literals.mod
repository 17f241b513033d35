MODULE num_literals
    ! num literal forms of manual 1.1.2 (syntax of num literal):
    ! exponent, leading/trailing point, hex 0x, octal 0o, binary 0b.
    PROC main()
        TPWrite "a=" \Num:=3E2;
        TPWrite "b=" \Num:=245E-2;
        TPWrite "c=" \Num:=.5;
        TPWrite "d=" \Num:=3.;
        TPWrite "e=" \Num:=1e1;
        TPWrite "f=" \Num:=0x1F;
        TPWrite "g=" \Num:=0o17;
        TPWrite "h=" \Num:=0b101;
        TPWrite "i=" \Num:=-0.345;
        TPWrite "j=" \Num:=2.5E-1;
        TPWrite "k=" \Num:=0XFF;
        TPWrite "l=" \Num:=1E+3;
    ENDPROC
ENDMODULE
