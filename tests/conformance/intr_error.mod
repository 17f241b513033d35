MODULE intr_error
    ! IError (manual 1.11, 1.12): an interrupt for event-log entries of a domain and
    ! type; in its trap GetTrapData and ReadErrData give the entry's domain, number,
    ! type, title and texts. ErrLog without \W or \I logs an error in the user domain
    ! (USER_DEF_ERR, 8); with \W a warning, which TYPE_ERR does not take.
    VAR intnum on_error;
    VAR trapdata event;
    VAR errdomain domain;
    VAR num id;
    VAR errtype kind;
    VAR string title;
    VAR string first;

    PROC main()
        CONNECT on_error WITH error_trap;
        IError COMMON_ERR, TYPE_ERR, on_error;
        ErrLog 4800 \W, "only a warning", ERRSTR_EMPTY, ERRSTR_EMPTY, ERRSTR_EMPTY, ERRSTR_EMPTY;
        TPWrite "after the warning";
        ErrLog 4801, "Gripper lost", "part dropped", ERRSTR_EMPTY, ERRSTR_EMPTY, ERRSTR_EMPTY;
        TPWrite "after the error";
    ENDPROC

    TRAP error_trap
        GetTrapData event;
        ReadErrData event, domain, id, kind \Title:=title \Str1:=first;
        TPWrite "user domain " \Bool:=domain = USER_DEF_ERR;
        TPWrite "id " \Num:=id;
        TPWrite "an error " \Bool:=kind = TYPE_ERR;
        TPWrite "title " + title;
        TPWrite "first " + first;
    ENDTRAP
ENDMODULE
