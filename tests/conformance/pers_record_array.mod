MODULE pers_record_array
    ! Components and elements of persistents can be read and written.
    PERS pos home := [100, 200, 300];
    PERS num tbl{3} := [1, 2, 3];

    PROC main()
        VAR num sum := 0;
        VAR pos one := [1, 1, 1];
        home.z := home.z + 50;
        TPWrite "home.z=" \Num:=home.z;
        tbl{2} := 20;
        FOR i FROM 1 TO 3 DO
            sum := sum + tbl{i};
        ENDFOR
        TPWrite "sum=" \Num:=sum;
        home := home + one;
        TPWrite "home=" \Num:=home.x + home.y + home.z;
    ENDPROC
ENDMODULE
