MODULE interp_concat_three
    ! a + b + "literal" on strings: the executor joins the three at once. The result
    ! must be the same as two additions, and a result over 80 characters must still
    ! raise ERR_STRTOOLNG (TRYNEXT leaves the variable unchanged).
    PROC main()
        VAR string s10 := "0123456789";
        VAR string s40;
        VAR string s;
        s40 := s10 + s10 + s10 + s10;
        ! 40 + 39 + 1 = 80 characters: fits.
        s := s40 + StrPart(s40, 1, 39) + "!";
        TPWrite "len=" \Num:=StrLen(s);
        TPWrite StrPart(s, 76, 5);
        ! 40 + 40 + 1 = 81 characters: too long.
        s := s40 + s40 + "?";
        TPWrite "next statement";
        ! Short pieces, several times in a row.
        s := "";
        FOR i FROM 1 TO 3 DO
            s := s + NumToStr(i, 0) + ";";
        ENDFOR
        TPWrite s;
    ERROR
        IF ERRNO = ERR_STRTOOLNG THEN
            TPWrite "string too long, len=" \Num:=StrLen(s);
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
