MODULE err_arr_outofbnd
    ! ERR_OUTOFBND with no handler stops execution.
    PROC main()
        VAR num a{3} := [1, 2, 3];
        VAR num sum := 0;
        FOR i FROM 1 TO 4 DO
            sum := sum + a{i};
            TPWrite "sum=" \Num:=sum;
        ENDFOR
        TPWrite "not reached";
    ENDPROC
ENDMODULE
