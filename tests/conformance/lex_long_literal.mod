MODULE lex_long_literal
    ! A string literal may have up to 80 characters (manual 1.1.2); escapes
    ! count as one character each.
    PROC main()
        VAR string s80 := "12345678901234567890123456789012345678901234567890123456789012345678901234567890";
        VAR string e := "\41\42""\\";
        TPWrite "len=" \Num:=StrLen(s80);
        TPWrite "tail=" + StrPart(s80, 75, 6);
        TPWrite "e=" + e;
        TPWrite "elen=" \Num:=StrLen(e);
    ENDPROC
ENDMODULE
