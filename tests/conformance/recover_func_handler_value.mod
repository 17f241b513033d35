MODULE recover_func_handler_value
    ! A FUNC handler turns an error into a fallback return value.
    VAR num table{3} := [10, 20, 30];

    FUNC num lookup(num i)
        RETURN table{i};
    ERROR
        IF ERRNO = ERR_OUTOFBND RETURN -1;
    ENDFUNC

    PROC main()
        FOR i FROM 0 TO 4 DO
            TPWrite "lookup " + ValToStr(i) + " = " + ValToStr(lookup(i));
        ENDFOR
    ENDPROC
ENDMODULE
