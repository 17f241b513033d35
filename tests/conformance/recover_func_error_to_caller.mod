MODULE recover_func_error_to_caller
    ! An error inside a FUNC without handler, called in an expression,
    ! propagates to the caller; TRYNEXT skips the whole assignment.
    VAR num table{3} := [10, 20, 30];

    FUNC num lookup(num i)
        RETURN table{i};
    ENDFUNC

    PROC main()
        VAR num v := -1;
        v := lookup(2);
        TPWrite "v=" \Num:=v;
        v := lookup(5) + 1000;
        TPWrite "v=" \Num:=v;
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            TPWrite "bad index";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
