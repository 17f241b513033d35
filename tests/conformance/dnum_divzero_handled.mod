MODULE dnum_divzero_handled
    ! Division by zero on dnum raises ERR_DIVZERO like num (semantics 2.1).
    PROC main()
        VAR dnum zero := 0;
        VAR dnum d := 9;
        d := d / zero;
        TPWrite "d=" \Dnum:=d;
        d := d DIV zero;
        TPWrite "end";
    ERROR
        IF ERRNO = ERR_DIVZERO THEN
            TPWrite "dnum division by zero";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
