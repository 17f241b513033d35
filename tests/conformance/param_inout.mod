MODULE param_inout
    ! INOUT parameters: the routine reads and writes the argument itself.
    PROC double(INOUT num x)
        x := x * 2;
    ENDPROC

    PROC main()
        VAR num v := 3;
        VAR num arr{3} := [1, 2, 3];
        double v;
        double v;
        TPWrite "v=" \Num:=v;
        double arr{3};
        TPWrite "arr3=" \Num:=arr{3};
        TPWrite "arr2=" \Num:=arr{2};
    ENDPROC
ENDMODULE
