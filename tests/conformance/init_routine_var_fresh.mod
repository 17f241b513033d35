MODULE init_routine_var_fresh
    ! Routine data is volatile (manual 1.2.2, storage class): every call gets
    ! new storage, set from the initial value or the default again.
    PROC counter()
        VAR num cnt;
        VAR num ten := 10;
        cnt := cnt + 1;
        ten := ten + 1;
        TPWrite "cnt=" \Num:=cnt;
        TPWrite "ten=" \Num:=ten;
    ENDPROC

    PROC main()
        counter;
        counter;
        counter;
    ENDPROC
ENDMODULE
