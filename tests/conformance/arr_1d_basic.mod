MODULE arr_1d_basic
    ! One-dimensional array, indexed from 1 (manual 1.3.2).
    PROC main()
        VAR num a{5};
        VAR num sum := 0;
        FOR i FROM 1 TO 5 DO
            a{i} := i * i;
        ENDFOR
        TPWrite "first=" \Num:=a{1};
        TPWrite "last=" \Num:=a{5};
        FOR i FROM 1 TO Dim(a, 1) DO
            sum := sum + a{i};
        ENDFOR
        TPWrite "sum=" \Num:=sum;
        TPWrite "dim=" \Num:=Dim(a, 1);
    ENDPROC
ENDMODULE
