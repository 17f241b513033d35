MODULE cmp_arrays
    ! = and <> on whole arrays of the same type and size: equal when all
    ! elements are equal.
    PROC main()
        VAR num a{3} := [1, 2, 3];
        VAR num b{3} := [1, 2, 3];
        VAR num c{3} := [1, 2, 4];
        VAR string s{2} := ["x", "y"];
        VAR string t{2} := ["x", "y"];
        TPWrite "a=b " \Bool:=a = b;
        TPWrite "a=c " \Bool:=a = c;
        TPWrite "a<>c " \Bool:=a <> c;
        TPWrite "s=t " \Bool:=s = t;
        c{3} := 3;
        TPWrite "a=c now " \Bool:=a = c;
        t{1} := "z";
        TPWrite "s<>t now " \Bool:=s <> t;
    ENDPROC
ENDMODULE
