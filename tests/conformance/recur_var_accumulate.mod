MODULE recur_var_accumulate
    ! A VAR parameter passed down a recursive chain refers to the same
    ! variable at every level.
    PROC sumTo(num n, VAR num acc)
        IF n = 0 RETURN;
        acc := acc + n;
        sumTo n - 1, acc;
    ENDPROC

    PROC main()
        VAR num total := 0;
        sumTo 10, total;
        TPWrite "total=" \Num:=total;
        sumTo 3, total;
        TPWrite "total=" \Num:=total;
    ENDPROC
ENDMODULE
