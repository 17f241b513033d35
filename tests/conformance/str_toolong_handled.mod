MODULE str_toolong_handled
    ! A concatenation longer than 80 characters raises ERR_STRTOOLNG, which is
    ! recoverable (semantics 2.5). After TRYNEXT the variable is unchanged.
    PROC main()
        VAR string s10 := "0123456789";
        VAR string s;
        s := s10 + s10 + s10 + s10 + s10 + s10 + s10 + s10;
        s := s + "x";
        TPWrite "len=" \Num:=StrLen(s);
    ERROR
        IF ERRNO = ERR_STRTOOLNG THEN
            TPWrite "string too long";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
