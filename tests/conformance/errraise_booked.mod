MODULE errraise_booked
    ! ErrRaise logs the event, then raises the number that BookErrNo gave ERR_BATT;
    ! the handler recognises it through ERRNO and TRYNEXT goes on with the next
    ! instruction. The title is Argument1; ERRSTR_TASK is the task name,
    ! ERRSTR_CONTEXT where it happened, ERRSTR_UNUSED is left out.
    VAR errnum ERR_BATT := -1;

    PROC main()
        BookErrNo ERR_BATT;
        check_battery;
        TPWrite "after";
    ENDPROC

    PROC check_battery()
        ErrRaise "ERR_BATT", 4810, "Battery low", ERRSTR_TASK, "Replace it", ERRSTR_CONTEXT, ERRSTR_UNUSED;
        TPWrite "next instruction";
    ERROR
        IF ERRNO = ERR_BATT THEN
            TPWrite "handled";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
