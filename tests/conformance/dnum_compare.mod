MODULE dnum_compare
    ! Relational operators on dnum (manual 1.3.1, logical expressions).
    PROC main()
        VAR dnum a := 3;
        VAR dnum b := 5;
        TPWrite "lt=" \Bool:=a < b;
        TPWrite "le=" \Bool:=a <= b;
        TPWrite "eq=" \Bool:=a = b;
        TPWrite "ge=" \Bool:=a >= b;
        TPWrite "gt=" \Bool:=a > b;
        TPWrite "ne=" \Bool:=a <> b;
        b := a;
        TPWrite "eq2=" \Bool:=a = b;
    ENDPROC
ENDMODULE
