MODULE param_var_element_component
    ! A VAR argument may be a whole variable, an array element or a record
    ! component (manual 1.1.5: entire, element or component).
    PROC addTen(VAR num x)
        x := x + 10;
    ENDPROC

    PROC main()
        VAR num n := 1;
        VAR num arr{3} := [1, 2, 3];
        VAR pos p := [1, 2, 3];
        VAR pos pts{2} := [[1, 1, 1], [2, 2, 2]];
        VAR num m{2, 2} := [[1, 2], [3, 4]];
        addTen n;
        addTen arr{2};
        addTen p.y;
        addTen pts{2}.z;
        addTen m{2, 1};
        TPWrite "n=" \Num:=n;
        TPWrite "arr2=" \Num:=arr{2};
        TPWrite "p.y=" \Num:=p.y;
        TPWrite "pts2z=" \Num:=pts{2}.z;
        TPWrite "pts2x=" \Num:=pts{2}.x;
        TPWrite "m21=" \Num:=m{2, 1};
    ENDPROC
ENDMODULE
