MODULE arr_assign_copy
    ! Whole-array assignment copies the values (manual 1.3.2: row := column).
    PROC main()
        VAR num row{3};
        VAR num column{3} := [7, 8, 9];
        VAR num value;
        value := column{3};
        TPWrite "value=" \Num:=value;
        row := column;
        column{1} := 99;
        TPWrite "row1=" \Num:=row{1};
        TPWrite "column1=" \Num:=column{1};
        row{2} := 0;
        TPWrite "column2=" \Num:=column{2};
    ENDPROC
ENDMODULE
