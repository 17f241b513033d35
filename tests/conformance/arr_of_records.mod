MODULE arr_of_records
    ! Arrays of records: element component access pts{i}.y.
    PROC main()
        VAR pos pts{3};
        VAR pos one := [1, 1, 1];
        VAR num total := 0;
        pts{2}.y := 5;
        pts{3} := [7, 8, 9];
        pts{1} := pts{3} + one;
        FOR i FROM 1 TO 3 DO
            total := total + pts{i}.x + pts{i}.y + pts{i}.z;
        ENDFOR
        TPWrite "p2y=" \Num:=pts{2}.y;
        TPWrite "p1z=" \Num:=pts{1}.z;
        TPWrite "total=" \Num:=total;
    ENDPROC
ENDMODULE
