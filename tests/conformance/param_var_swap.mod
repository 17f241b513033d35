MODULE param_var_swap
    ! VAR parameters refer to the caller's variables (manual 1.1.5).
    PROC swap(VAR num a, VAR num b)
        VAR num t;
        t := a;
        a := b;
        b := t;
    ENDPROC

    PROC swapStr(VAR string a, VAR string b)
        VAR string t;
        t := a;
        a := b;
        b := t;
    ENDPROC

    PROC main()
        VAR num x := 1;
        VAR num y := 2;
        VAR string s := "left";
        VAR string t := "right";
        swap x, y;
        TPWrite "x=" \Num:=x;
        TPWrite "y=" \Num:=y;
        swapStr s, t;
        TPWrite s + " " + t;
    ENDPROC
ENDMODULE
