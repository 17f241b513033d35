MODULE param_in_copy
    ! A normal (IN) parameter acts as a routine variable: changing it does not
    ! change the argument (manual 1.1.5, parameters).
    PROC modify(num x)
        x := x + 100;
        TPWrite "inside=" \Num:=x;
    ENDPROC

    PROC main()
        VAR num a := 1;
        VAR num arr{2} := [5, 6];
        modify a;
        TPWrite "after=" \Num:=a;
        modify a + 1;
        modify arr{2};
        TPWrite "arr2=" \Num:=arr{2};
    ENDPROC
ENDMODULE
