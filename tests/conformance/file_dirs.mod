MODULE file_dirs
    ! MakeDir, OpenDir/ReadDir/CloseDir, RemoveDir and IsFile \Directory (manual §1.16).
    ! IsFile with a kind raises ERR_FILEACC for a path that does not exist (public RAPID
    ! programs make a missing directory in that handler); without a kind it is FALSE.
    ! ReadDir gives "." and ".." first (the controller's file system lists them; public
    ! RAPID programs skip two entries), then, here, the names in alphabetical order.
    VAR dir d;

    PROC main()
        VAR string name;
        VAR iodev f;
        MakeDir "HOME:/work";
        MakeDir "HOME:/work/sub";
        Open "HOME:/work/b.txt", f \Write;
        Close f;
        Open "HOME:/work/a.txt", f \Write;
        Close f;
        TPWrite "dir=" \Bool:=IsFile("HOME:/work" \Directory);
        TPWrite "file is dir=" \Bool:=IsFile("HOME:/work/a.txt" \Directory);
        OpenDir d, "HOME:/work";
        WHILE ReadDir(d, name) DO
            TPWrite "entry " + name;
        ENDWHILE
        TPWrite "after end=" \Bool:=ReadDir(d, name);
        CloseDir d;
        try "make existing", 1;
        try "remove non-empty", 2;
        try "open missing", 3;
        try "read closed", 4;
        try "remove a device", 5;
        try "IsFile \\Directory of a missing path", 6;
        RemoveFile "HOME:/work/a.txt";
        RemoveFile "HOME:/work/b.txt";
        RemoveDir "HOME:/work/sub";
        RemoveDir "HOME:/work";
        TPWrite "gone=" \Bool:=NOT IsFile("HOME:/work");
    ENDPROC

    PROC try(string what, num which)
        VAR string name;
        TEST which
        CASE 1:
            MakeDir "HOME:/work";
        CASE 2:
            RemoveDir "HOME:/work";
        CASE 3:
            OpenDir d, "HOME:/nowhere";
        CASE 4:
            IF ReadDir(d, name) TPWrite "read " + name;
        CASE 5:
            RemoveDir "HOME:";
        CASE 6:
            IF IsFile("HOME:/nowhere" \Directory) TPWrite "exists";
        ENDTEST
        TPWrite what + ": no error";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite what + ": ERR_FILEACC";
        RETURN;
    ENDPROC
ENDMODULE
