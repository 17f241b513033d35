MODULE io_signal_not_connected_handled
    ! ERR_NO_ALIASIO_DEF is a recoverable error (manual 1.9): an ERROR handler takes it,
    ! for a digital output, a group input and an element of an array of signals alike.
    VAR signaldo do_lamp;
    VAR signalgi gi_code;
    VAR signalai sensors{2};
    VAR num seen := 0;

    PROC read(num which)
        VAR num v;
        TEST which
        CASE 1:
            v := do_lamp;
        CASE 2:
            v := gi_code + 1;
        CASE 3:
            IF sensors{2} > 5.2 v := 1;
        ENDTEST
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_NO_ALIASIO_DEF THEN
            seen := seen + 1;
            RETURN;
        ENDIF
    ENDPROC

    PROC main()
        FOR k FROM 1 TO 3 DO
            read k;
        ENDFOR
        TPWrite "ERR_NO_ALIASIO_DEF taken " \Num:=seen;
    ENDPROC
ENDMODULE
