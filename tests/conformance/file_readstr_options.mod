MODULE file_readstr_options
    ! ReadStr's options (manual ReadStr): \Delim adds delimiters to the line feed;
    ! without \DiscardHeaders a delimiter at the position gives an empty string, with it
    ! heading delimiters are skipped; \RemoveCR drops a trailing carriage return; a
    ! field longer than 80 characters continues at the next read; \Line:=n reads line n.
    PROC main()
        VAR iodev f;
        VAR string s;
        VAR string long := "";
        Open "HOME:/s.txt", f \Write;
        Write f, "a b,,c";
        Write f, "dos\0D";
        FOR i FROM 1 TO 8 DO
            long := long + "0123456789";
        ENDFOR
        ! A line of 90 characters (a string holds at most 80).
        Write f, long \NoNewLine;
        Write f, "0123456789";
        Write f, "tail";
        Close f;
        Open "HOME:/s.txt", f \Read;
        TPWrite "[" + ReadStr(f \Delim:=" ,") + "]";
        TPWrite "[" + ReadStr(f \Delim:=" ,") + "]";
        TPWrite "[" + ReadStr(f \Delim:=" ,") + "]";
        TPWrite "[" + ReadStr(f \Delim:=" ," \DiscardHeaders) + "]";
        TPWrite "len=" \Num:=StrLen(ReadStr(f));
        Rewind f;
        s := ReadStr(f \RemoveCR \Line:=2);
        TPWrite "[" + s + "] len=" + NumToStr(StrLen(s), 0);
        s := ReadStr(f);
        TPWrite "part1 len=" \Num:=StrLen(s);
        s := ReadStr(f);
        TPWrite "part2=" + s;
        TPWrite "line4=" + ReadStr(f \Line:=4);
        TPWrite "line9=" + ReadStr(f \Line:=9);
        Close f;
    ENDPROC
ENDMODULE
