MODULE str_toolong_in_func
    ! ERR_STRTOOLNG inside a FUNC without handler propagates to the caller's
    ! handler (manual 1.12, system error handler).
    FUNC string twice(string s)
        RETURN s + s;
    ENDFUNC

    PROC main()
        VAR string s;
        s := twice("0123456789");
        TPWrite "len=" \Num:=StrLen(s);
        ! 20 -> 40 -> 80 -> 160: the third call fails
        s := twice(twice(twice(s)));
        TPWrite "len=" \Num:=StrLen(s);
    ERROR
        IF ERRNO = ERR_STRTOOLNG THEN
            TPWrite "caught in main";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
