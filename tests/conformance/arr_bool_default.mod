MODULE arr_bool_default
    ! Elements of an uninitialised bool array are FALSE (manual 1.2.2).
    PROC main()
        VAR bool flags{4};
        VAR num count := 0;
        flags{2} := TRUE;
        FOR i FROM 1 TO 4 DO
            IF flags{i} count := count + 1;
        ENDFOR
        TPWrite "count=" \Num:=count;
        TPWrite "f1=" \Bool:=flags{1};
        TPWrite "f2=" \Bool:=flags{2};
    ENDPROC
ENDMODULE
