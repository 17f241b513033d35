MODULE num_incr_add_clear
    ! Simple calculation instructions of manual 1.15: Incr, Decr, Add, Clear,
    ! also on an array element and a record component.
    PROC main()
        VAR num n := 10;
        VAR num a{3} := [1, 2, 3];
        VAR pos p := [1, 2, 3];
        Incr n;
        TPWrite "incr=" \Num:=n;
        Decr n;
        Decr n;
        TPWrite "decr=" \Num:=n;
        Add n, 5;
        TPWrite "add=" \Num:=n;
        Add n, -20;
        TPWrite "add2=" \Num:=n;
        Clear n;
        TPWrite "clear=" \Num:=n;
        Incr a{2};
        Add a{3}, 10;
        TPWrite "a2=" \Num:=a{2};
        TPWrite "a3=" \Num:=a{3};
        Decr p.z;
        TPWrite "pz=" \Num:=p.z;
    ENDPROC
ENDMODULE
