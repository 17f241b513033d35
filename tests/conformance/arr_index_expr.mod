MODULE arr_index_expr
    ! Index expressions, including an array element used as index.
    PROC main()
        VAR num a{3} := [3, 1, 2];
        VAR num i := 1;
        TPWrite "a{i+1}=" \Num:=a{i + 1};
        TPWrite "a{a{1}}=" \Num:=a{a{1}};
        TPWrite "a{a{a{2}}}=" \Num:=a{a{a{2}}};
        TPWrite "a{4 DIV 2}=" \Num:=a{4 DIV 2};
        a{a{2}} := 10;
        TPWrite "a1=" \Num:=a{1};
    ENDPROC
ENDMODULE
