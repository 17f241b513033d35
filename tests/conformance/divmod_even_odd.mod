MODULE divmod_even_odd
    ! MOD 2 in a FOR loop with TEST.
    PROC main()
        VAR num evens := 0;
        VAR num odds := 0;
        FOR i FROM 1 TO 9 DO
            TEST i MOD 2
            CASE 0:
                evens := evens + i;
            DEFAULT:
                odds := odds + i;
            ENDTEST
        ENDFOR
        TPWrite "evens=" \Num:=evens;
        TPWrite "odds=" \Num:=odds;
    ENDPROC
ENDMODULE
