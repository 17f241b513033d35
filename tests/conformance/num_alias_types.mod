MODULE num_alias_types
    ! Alias types (manual 1.2.1): dionum is an alias of num, so a dionum value
    ! can be assigned to a num (manual example). A user ALIAS behaves the same.
    ALIAS num distance;
    VAR num level;
    VAR dionum high_val := 1;
    VAR distance d1 := 250;

    PROC main()
        VAR num total;
        level := high_val;
        TPWrite "level=" \Num:=level;
        total := d1 * 2 + level;
        TPWrite "total=" \Num:=total;
        d1 := total;
        TPWrite "d1=" \Num:=d1;
    ENDPROC
ENDMODULE
