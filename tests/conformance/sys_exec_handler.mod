MODULE sys_exec_handler
    ! ExecHandler tells which handler of the calling routine runs (handler_type:
    ! HANDLER_NONE, HANDLER_BWD, HANDLER_ERR, HANDLER_UNDO); ExecLevel is
    ! LEVEL_NORMAL outside TRAP routines. A routine called from a handler runs no
    ! handler of its own: HANDLER_NONE there.
    VAR num zero := 0;
    VAR num x;

    FUNC string kind()
        TEST ExecHandler()
        CASE HANDLER_NONE:
            RETURN "none";
        CASE HANDLER_BWD:
            RETURN "backward";
        CASE HANDLER_ERR:
            RETURN "error";
        CASE HANDLER_UNDO:
            RETURN "undo";
        ENDTEST
        RETURN "?";
    ENDFUNC

    PROC report(string where)
        TPWrite where + ": called routine sees " + kind();
    ENDPROC

    PROC fail()
        x := 1 / zero;
    ERROR
        IF ExecHandler() = HANDLER_ERR TPWrite "in ERROR handler: HANDLER_ERR";
        report "ERROR";
        TRYNEXT;
    UNDO
        IF ExecHandler() = HANDLER_UNDO TPWrite "in UNDO handler: HANDLER_UNDO";
    ENDPROC

    PROC main()
        IF ExecHandler() = HANDLER_NONE TPWrite "main: HANDLER_NONE";
        IF ExecLevel() = LEVEL_NORMAL TPWrite "main: LEVEL_NORMAL";
        fail;
        TPWrite "back in main";
        inner;
    ENDPROC

    PROC inner()
        EXIT;
    UNDO
        TPWrite "inner UNDO: " \Num:=ExecHandler();
    ENDPROC
ENDMODULE
