MODULE for_basic
    ! FOR repeats its body for each value of the loop variable (manual 1.5).
    PROC main()
        VAR num sum := 0;
        FOR i FROM 1 TO 5 DO
            TPWrite "i=" \Num:=i;
            sum := sum + i;
        ENDFOR
        TPWrite "sum=" \Num:=sum;
    ENDPROC
ENDMODULE
