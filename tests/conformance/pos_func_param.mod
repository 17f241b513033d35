MODULE pos_func_param
    ! The manual's vecLen FUNC (manual 1.1.5) and a pos-returning FUNC.
    FUNC num vecLen(pos vector)
        RETURN Sqrt(Pow(vector.x, 2) + Pow(vector.y, 2) + Pow(vector.z, 2));
    ENDFUNC

    FUNC pos midpoint(pos a, pos b)
        RETURN (a + b) / 2;
    ENDFUNC

    PROC main()
        VAR pos m;
        VAR pos one := [1, 1, 1];
        TPWrite "len=" \Num:=vecLen([3, 4, 12]);
        m := midpoint([0, 0, 0], [10, 4, -6]);
        TPWrite "mx=" \Num:=m.x;
        TPWrite "my=" \Num:=m.y;
        TPWrite "mz=" \Num:=m.z;
        m := midpoint([1, 1, 1], [7, 9, 1]);
        TPWrite "len2=" \Num:=vecLen(m - one);
    ENDPROC
ENDMODULE
