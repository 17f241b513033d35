MODULE num_average_loop
    ! Sum, mean, minimum and maximum of a data table.
    CONST num data{8} := [4, 8, 15, 16, 23, 42, 2, 10];

    PROC main()
        VAR num sum := 0;
        VAR num lo;
        VAR num hi;
        lo := data{1};
        hi := data{1};
        FOR i FROM 1 TO Dim(data, 1) DO
            sum := sum + data{i};
            IF data{i} < lo lo := data{i};
            IF data{i} > hi hi := data{i};
        ENDFOR
        TPWrite "sum=" \Num:=sum;
        TPWrite "mean=" \Num:=sum / Dim(data, 1);
        TPWrite "min=" \Num:=lo;
        TPWrite "max=" \Num:=hi;
    ENDPROC
ENDMODULE
