MODULE str_escape
    ! String literal escapes (manual 1.1.2, string values): a double quote and
    ! a backslash are written twice; \hh is the character with hex code hh.
    PROC main()
        TPWrite "This string contains a "" character";
        TPWrite "This string contains a \\ character";
        TPWrite "\41\42\43";
        TPWrite "\6a\6B";
        TPWrite "len1=" \Num:=StrLen("""");
        TPWrite "len2=" \Num:=StrLen("\\");
        TPWrite "len3=" \Num:=StrLen("\07");
        TPWrite "len4=" \Num:=StrLen("a""b\5Cc");
    ENDPROC
ENDMODULE
