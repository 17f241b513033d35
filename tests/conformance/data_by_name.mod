MODULE data_by_name
    ! GetDataVal and SetDataVal reach module-level data through its name as text
    ! (case-insensitive, like every RAPID name). Value must have the data's type
    ! (else ERR_SYMBOL_TYPE); an unknown name gives ERR_SYM_ACCESS, and so does
    ! writing a constant; a task other than T_ROB1 gives ERR_TASKNAME.
    VAR num counter := 7;
    PERS string label := "first";
    CONST num limit := 99;
    VAR pos offset := [1, 2, 3];
    VAR num grid{2} := [10, 20];

    PROC main()
        VAR num n;
        VAR string s;
        VAR pos p;
        VAR num pair{2};
        GetDataVal "counter", n;
        TPWrite "counter " \Num:=n;
        SetDataVal "COUNTER", n + 1;
        TPWrite "counter now " \Num:=counter;
        SetDataVal "label" \TaskName:="T_ROB1", "second";
        GetDataVal "Label", s;
        TPWrite "label " + s;
        GetDataVal "offset", p;
        TPWrite "offset " \Pos:=p;
        GetDataVal "grid", pair;
        TPWrite "grid " \Num:=pair{1} + pair{2};
        GetDataVal "limit", n;
        TPWrite "limit " \Num:=n;
        try_get_bool;
        try_set_constant;
        try_unknown;
        try_other_task;
    ENDPROC

    ! rapid run runs the one task T_ROB1: another task name is ERR_TASKNAME.
    PROC try_other_task()
        VAR num n;
        GetDataVal "counter" \TaskName:="T_ROB2", n;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_TASKNAME TPWrite "no such task";
        RETURN;
    ENDPROC

    PROC try_get_bool()
        VAR bool b;
        GetDataVal "counter", b;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_SYMBOL_TYPE TPWrite "type mismatch";
        RETURN;
    ENDPROC

    PROC try_set_constant()
        SetDataVal "limit", 5;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_SYM_ACCESS TPWrite "constant kept " \Num:=limit;
        RETURN;
    ENDPROC

    PROC try_unknown()
        VAR num n;
        GetDataVal "nosuch", n;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_SYM_ACCESS TPWrite "unknown name";
        RETURN;
    ENDPROC
ENDMODULE
