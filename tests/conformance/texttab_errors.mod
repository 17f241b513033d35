MODULE texttab_errors
    ! ERR_TXTNOEXIST for a table name that is not installed (TextTabGet) and for a table
    ! number or index that does not exist (TextGet); ERR_FILEOPEN when TextTabInstall
    ! cannot open its file, also for a path that leaves its device (docs/semantics.md).
    ! Two tables are numbered apart; a text cannot grow past 80 characters (ERR_STRTOOLNG).
    PROC main()
        VAR iodev f;
        VAR num one;
        VAR num two;
        Open "HOME:/one.txt", f \Write;
        Write f, "one::";
        Write f, "1:";
        Write f, "first {1}";
        Close f;
        Open "HOME:/two.txt", f \Write;
        Write f, "two::";
        Write f, "1:";
        Write f, "second";
        Close f;
        TPWrite "missing file: " + install("HOME:/none.eng");
        TPWrite "escape: " + install("HOME:/../two.txt");
        TPWrite "one: " + install("HOME:/one.txt");
        TPWrite "two: " + install("HOME:/two.txt");
        one := TextTabGet("one");
        two := TextTabGet("two");
        TPWrite "apart=" \Bool:=(one <> two);
        TPWrite TextGet(one, 1 \Arg1:="A") + "/" + TextGet(two, 1);
        TPWrite "no table: " + tabnum("three");
        TPWrite "no index: " + text(one, 2);
        TPWrite "no number: " + text(one + two, 1);
        TPWrite "fraction: " + text(one, 0.5);
        TPWrite "too long: " + text(one, 1);
    ENDPROC

    FUNC string install(string path)
        TextTabInstall path;
        RETURN "ok";
    ERROR
        IF ERRNO = ERR_FILEOPEN RETURN "ERR_FILEOPEN";
    ENDFUNC

    FUNC string tabnum(string name)
        VAR num n;
        n := TextTabGet(name);
        RETURN "found";
    ERROR
        IF ERRNO = ERR_TXTNOEXIST RETURN "ERR_TXTNOEXIST";
    ENDFUNC

    FUNC string text(num tab, num index)
        VAR string long := "0123456789012345678901234567890123456789012345678901234567890123456789012345";
        IF index = 1 RETURN TextGet(tab, index \Arg1:=long);
        RETURN TextGet(tab, index);
    ERROR
        IF ERRNO = ERR_TXTNOEXIST RETURN "ERR_TXTNOEXIST";
        IF ERRNO = ERR_STRTOOLNG RETURN "ERR_STRTOOLNG";
    ENDFUNC
ENDMODULE
