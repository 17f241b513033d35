MODULE str_len80_ok
    ! A string may hold up to 80 characters (manual 1.1.2): exactly 80 is fine.
    PROC main()
        VAR string s10 := "0123456789";
        VAR string s;
        s := s10 + s10 + s10 + s10 + s10 + s10 + s10 + s10;
        TPWrite "len=" \Num:=StrLen(s);
        TPWrite "tail=" + StrPart(s, 71, 10);
        TPWrite "eq=" \Bool:=StrPart(s, 1, 10) = s10;
    ENDPROC
ENDMODULE
