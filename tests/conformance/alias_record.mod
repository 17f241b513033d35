MODULE alias_record
    ! An ALIAS of a record type (manual 1.2.1): values of the alias and of
    ! the base type mix freely; arithmetic gives the base type (manual 1.3.1
    ! note ii).
    ALIAS pos vec;

    PROC main()
        VAR vec a := [1, 2, 3];
        VAR vec b := [4, 5, 6];
        VAR pos c;
        c := a + b;
        TPWrite "c.z=" \Num:=c.z;
        a := c;
        TPWrite "a.x=" \Num:=a.x;
        TPWrite "same=" \Bool:=a = c;
    ENDPROC
ENDMODULE
