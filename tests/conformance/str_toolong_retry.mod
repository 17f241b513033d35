MODULE str_toolong_retry
    ! ERR_STRTOOLNG fixed in the handler, then RETRY runs the failed
    ! statement again (manual 1.12).
    PROC main()
        VAR string s10 := "0123456789";
        VAR string s;
        s := s10 + s10 + s10 + s10 + s10 + s10 + s10 + s10;
        s := s + "x";
        TPWrite "len=" \Num:=StrLen(s);
        TPWrite "end=" + StrPart(s, 68, 4);
    ERROR
        IF ERRNO = ERR_STRTOOLNG THEN
            TPWrite "shortening";
            s := StrPart(s, 1, 70);
            RETRY;
        ENDIF
    ENDPROC
ENDMODULE
