MODULE while_and_condition
    ! A WHILE condition combining relations with AND (relations bind
    ! tighter, manual 1.3.5).
    PROC main()
        VAR num data{6} := [3, 8, 1, 0, 7, 2];
        VAR num i := 1;
        VAR num sum := 0;
        WHILE i <= 3 AND data{i} > 0 DO
            sum := sum + data{i};
            i := i + 1;
        ENDWHILE
        TPWrite "i=" \Num:=i;
        TPWrite "sum=" \Num:=sum;
    ENDPROC
ENDMODULE
