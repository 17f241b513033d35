MODULE pos_cross_dot
    ! pos * pos is the cross product (manual 1.3.1); CrossProd, DotProd and
    ! VectMagn (manual 1.15). Unit-axis results are compared with =, which
    ! does not depend on how a zero is printed.
    PROC show(string label, pos p)
        TPWrite label + "=" + ValToStr(p.x) + "," + ValToStr(p.y) + "," + ValToStr(p.z);
    ENDPROC

    PROC main()
        VAR pos ex := [1, 0, 0];
        VAR pos ey := [0, 1, 0];
        VAR pos ez := [0, 0, 1];
        VAR pos a := [1, 2, 3];
        VAR pos b := [4, 5, 6];
        VAR pos r;
        TPWrite "x*y=z " \Bool:=ex * ey = ez;
        TPWrite "y*x=-z " \Bool:=ey * ex = -ez;
        TPWrite "y*z=x " \Bool:=ey * ez = ex;
        r := a * b;
        show "axb", r;
        r := CrossProd(a, b);
        show "cross", r;
        a := [2, 0, 1];
        b := [1, 3, 0];
        r := a * b;
        show "c2", r;
        TPWrite "dot=" \Num:=DotProd([1, 2, 3], [4, 5, 6]);
        TPWrite "magn=" \Num:=VectMagn([3, 4, 0]);
        TPWrite "magn2=" \Num:=VectMagn([2, 3, 6]);
    ENDPROC
ENDMODULE
