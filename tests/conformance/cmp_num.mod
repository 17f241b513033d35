MODULE cmp_num
    ! Relational operators on num (manual 1.3.1).
    PROC main()
        VAR num a := 3;
        VAR num b := 5;
        TPWrite "lt=" \Bool:=a < b;
        TPWrite "le=" \Bool:=a <= b;
        TPWrite "eq=" \Bool:=a = b;
        TPWrite "ge=" \Bool:=a >= b;
        TPWrite "gt=" \Bool:=a > b;
        TPWrite "ne=" \Bool:=a <> b;
        TPWrite "le3=" \Bool:=a <= 3;
        TPWrite "ge3=" \Bool:=a >= 3;
        TPWrite "neg=" \Bool:=-1 < 0;
        TPWrite "dec=" \Bool:=2.5 > 2.25;
    ENDPROC
ENDMODULE
