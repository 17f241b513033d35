MODULE param_aliasing
    ! Two VAR parameters bound to the same variable are both that variable
    ! (updating a VAR parameter updates the argument itself, manual 1.1.5).
    PROC addBoth(VAR num x, VAR num y)
        x := x + 1;
        y := y + 10;
    ENDPROC

    PROC copyInto(num src, VAR num dst)
        dst := src * 2;
        dst := dst + src;
    ENDPROC

    PROC main()
        VAR num a := 0;
        VAR num b := 5;
        addBoth a, a;
        TPWrite "a=" \Num:=a;
        ! src is a copy taken at the call, so it stays 5 after dst changes
        copyInto b, b;
        TPWrite "b=" \Num:=b;
    ENDPROC
ENDMODULE
