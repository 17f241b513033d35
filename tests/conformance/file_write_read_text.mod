MODULE file_write_read_text
    ! Write (manual Write): the text, then the value in TPWrite's format, then a line
    ! feed unless \NoNewLine. ReadStr (manual ReadStr) returns one line per call without
    ! its line feed, and the string EOF once the file is at its end.
    PROC main()
        VAR iodev f;
        VAR string s;
        VAR num n := 0;
        Open "HOME:/log.txt", f \Write;
        Write f, "plain";
        Write f, "n=" \Num:=42;
        Write f, "b=" \Bool:=TRUE;
        Write f, "p=" \Pos:=[1,2.5,-3];
        Write f, "o=" \Orient:=[1,0,0,0];
        Write f, "d=" \Dnum:=123456789;
        Write f, "no" \NoNewLine;
        Write f, "new" \NoNewLine;
        Write f, "line";
        Write f, "";
        Write f, "last";
        Close f;
        Open "HOME:/log.txt", f \Read;
        s := ReadStr(f);
        WHILE s <> EOF DO
            n := n + 1;
            TPWrite NumToStr(n, 0) + ":" + s;
            s := ReadStr(f);
        ENDWHILE
        ! Still at the end: EOF again.
        TPWrite ReadStr(f);
        Close f;
    ENDPROC
ENDMODULE
