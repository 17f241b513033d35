MODULE late_binding_array
    ! Late binding through a string array (manual 1.1.5, third variant).
    VAR string procname{3} := ["proc1", "proc2", "proc3"];

    PROC proc1(num x, num y, num z)
        TPWrite "proc1 sum " \Num:=x + y + z;
    ENDPROC

    PROC proc2(num x, num y, num z)
        TPWrite "proc2 product " \Num:=x * y * z;
    ENDPROC

    PROC proc3(num x, num y, num z)
        TPWrite "proc3 max " \Num:=Max(x, Max(y, z));
    ENDPROC

    PROC main()
        VAR num x := 2;
        VAR num y := 3;
        VAR num z := 4;
        FOR product_id FROM 3 TO 1 STEP -1 DO
            % procname{product_id} % x, y, z;
        ENDFOR
    ENDPROC
ENDMODULE
