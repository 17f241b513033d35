MODULE sym_setall
    ! SetAllDataVal sets every VAR and PERS of the type whose name matches \Object
    ! (whole name, any case) to Value (docs/semantics.md). Constants and arrays of the
    ! type are left alone; a Value of another type raises ERR_SYMBOL_TYPE and sets
    ! nothing; a malformed pattern raises ERR_ARGVALERR.
    VAR num cnt1 := 1;
    VAR num cnt2 := 2;
    PERS num cnt3 := 3;
    CONST num cnt4 := 4;
    VAR num keep := 9;
    VAR num cnts{2} := [1, 2];
    VAR bool flag1 := FALSE;
    LOCAL VAR bool flag2 := FALSE;

    PROC main()
        SetAllDataVal "num" \Object:="CNT.*", 0;
        TPWrite "cnt1=" \Num:=cnt1;
        TPWrite "cnt2=" \Num:=cnt2;
        TPWrite "cnt3=" \Num:=cnt3;
        TPWrite "cnt4=" \Num:=cnt4;
        TPWrite "keep=" \Num:=keep;
        TPWrite "cnts{1}=" \Num:=cnts{1};
        SetAllDataVal "bool", TRUE;
        TPWrite "flag1=" \Bool:=flag1;
        TPWrite "flag2=" \Bool:=flag2;
        TPWrite "type: " + setall("keep");
        TPWrite "keep=" \Num:=keep;
        TPWrite "pattern: " + setall("keep)");
    ENDPROC

    FUNC string setall(string pattern)
        SetAllDataVal "num" \Object:=pattern, "text";
        RETURN "ok";
    ERROR
        IF ERRNO = ERR_SYMBOL_TYPE RETURN "ERR_SYMBOL_TYPE";
        IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    ENDFUNC
ENDMODULE
