MODULE recover_handler_locals
    ! The handler sees the routine's data (manual 1.12: the scope of routine
    ! data includes the error handler) and may change it before RETRY.
    PROC main()
        VAR num vals{3} := [4, 0, 5];
        VAR num i := 1;
        VAR num sum := 0;
        WHILE i <= 3 DO
            sum := sum + 100 / vals{i};
            i := i + 1;
        ENDWHILE
        TPWrite "sum=" \Num:=sum;
    ERROR
        TPWrite "zero at " \Num:=i;
        vals{i} := 50;
        RETRY;
    ENDPROC
ENDMODULE
