MODULE recover_safediv
    ! The manual's safediv example (manual 1.12, error handlers): a FUNC
    ! handler that returns a value with RETURN.
    FUNC num safediv( num x, num y)
        RETURN x / y;
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "The number cannot be equal to 0";
            RETURN x;
        ENDIF
    ENDFUNC

    PROC main()
        TPWrite "r=" \Num:=safediv(10, 4);
        TPWrite "r=" \Num:=safediv(10, 0);
        TPWrite "sum=" \Num:=safediv(6, 3) + safediv(7, 0);
    ENDPROC
ENDMODULE
