MODULE err_str_toolong
    ! ERR_STRTOOLNG with no handler stops execution.
    PROC main()
        VAR string s40 := "0123456789012345678901234567890123456789";
        VAR string s;
        s := s40 + s40;
        TPWrite "len=" \Num:=StrLen(s);
        s := s + "!";
        TPWrite "not reached";
    ENDPROC
ENDMODULE
