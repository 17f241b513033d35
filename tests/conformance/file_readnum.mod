MODULE file_readnum
    ! ReadNum (manual ReadNum): reads the next field up to a delimiter (line feed, plus
    ! the characters of \Delim), skipping delimiters in front of it, and converts it to a
    ! num. At end of file it returns EOF_NUM; a field that is not a number raises
    ! ERR_RCVDATA.
    VAR iodev f;

    PROC main()
        VAR num n;
        VAR num sum := 0;
        Open "HOME:/nums.txt", f \Write;
        Write f, "12";
        Write f, "";
        Write f, "-3.5";
        Write f, "1,2;3";
        Write f, "1E3";
        Close f;
        Open "HOME:/nums.txt", f \Read;
        TPWrite "a=" \Num:=ReadNum(f);
        ! The empty line in front is skipped.
        TPWrite "b=" \Num:=ReadNum(f);
        n := ReadNum(f \Delim:=",;");
        WHILE n <> EOF_NUM DO
            sum := sum + n;
            n := ReadNum(f \Delim:=",;");
        ENDWHILE
        TPWrite "sum=" \Num:=sum;
        TPWrite "eof again=" \Bool:=(ReadNum(f) = EOF_NUM);
        Close f;
        bad_field;
    ENDPROC

    PROC bad_field()
        VAR num n;
        Open "HOME:/bad.txt", f \Write;
        Write f, "abc";
        Write f, "7";
        Close f;
        Open "HOME:/bad.txt", f \Read;
        n := ReadNum(f);
        TPWrite "n=" \Num:=n;
        Close f;
    ERROR
        IF ERRNO = ERR_RCVDATA THEN
            TPWrite "abc: ERR_RCVDATA";
            ! The bad field was consumed; the next read gives the next line.
            n := 0;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
