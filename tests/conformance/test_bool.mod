MODULE test_bool
    ! TEST on a bool expression.
    PROC main()
        FOR i FROM 1 TO 3 DO
            TEST i > 1
            CASE TRUE:
                TPWrite "big " \Num:=i;
            CASE FALSE:
                TPWrite "not big " \Num:=i;
            ENDTEST
        ENDFOR
    ENDPROC
ENDMODULE
