MODULE file_times
    ! FileTimeDnum (manual): a file's modification (default), access or status-change
    ! time in seconds since 1970-01-01, also as a stringdig with \StrDig. ModExist tells
    ! whether a module is loaded; ModTimeDnum gives the modification time of the file a
    ! loaded module came from, and raises ERR_MOD_NOTLOADED for any other name.
    PROC main()
        VAR iodev f;
        VAR dnum t;
        VAR stringdig digits;
        VAR dnum modtime;
        Open "HOME:/t.txt", f \Write;
        Write f, "x";
        Close f;
        t := FileTimeDnum("HOME:/t.txt");
        ! After 2020-09-13 (1600000000 s) and before 2100 (4102444800 s).
        TPWrite "plausible=" \Bool:=(t > 1600000000 AND t < 4102444800);
        TPWrite "modify=default " \Bool:=(FileTimeDnum("HOME:/t.txt" \ModifyTime) = t);
        TPWrite "access>0 " \Bool:=(FileTimeDnum("HOME:/t.txt" \AccessTime) > 0);
        TPWrite "statc>0 " \Bool:=(FileTimeDnum("HOME:/t.txt" \StatCTime) > 0);
        t := FileTimeDnum("HOME:/t.txt" \StrDig:=digits);
        TPWrite "digits=" \Num:=StrLen(digits);
        TPWrite "exists=" \Bool:=ModExist("file_times");
        TPWrite "case=" \Bool:=ModExist("FILE_TIMES");
        TPWrite "other=" \Bool:=ModExist("no_such_module");
        modtime := ModTimeDnum("file_times");
        TPWrite "module older=" \Bool:=(modtime > 1600000000 AND modtime <= t);
        modtime := ModTimeDnum("no_such_module");
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_MOD_NOTLOADED THEN
            TPWrite "no_such_module: ERR_MOD_NOTLOADED";
            missing_file;
            RETURN;
        ENDIF
    ENDPROC

    PROC missing_file()
        VAR dnum t;
        t := FileTimeDnum("HOME:/none.txt");
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite "missing file: ERR_FILEACC";
        RETURN;
    ENDPROC
ENDMODULE
