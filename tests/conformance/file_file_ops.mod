MODULE file_file_ops
    ! RemoveFile, RenameFile, CopyFile, FileSize and IsFile with its type switches
    ! (manual §1.16). RenameFile and CopyFile onto an existing file raise ERR_FILEEXIST;
    ! a missing source raises ERR_FILEACC, as does a path that climbs out of its device.
    PROC main()
        VAR iodev f;
        Open "HOME:/one.txt", f \Write;
        Write f, "12345";
        Close f;
        TPWrite "size=" \Num:=FileSize("HOME:/one.txt");
        CopyFile "HOME:/one.txt", "TEMP:/copy.txt";
        TPWrite "copy size=" \Num:=FileSize("TEMP:/copy.txt");
        RenameFile "TEMP:/copy.txt", "TEMP:/renamed.txt";
        TPWrite "old=" \Bool:=IsFile("TEMP:/copy.txt");
        TPWrite "new=" \Bool:=IsFile("TEMP:/renamed.txt");
        TPWrite "regular=" \Bool:=IsFile("TEMP:/renamed.txt" \RegFile);
        TPWrite "fifo=" \Bool:=IsFile("TEMP:/renamed.txt" \Fifo);
        TPWrite "block=" \Bool:=IsFile("TEMP:/renamed.txt" \BlockSpec);
        TPWrite "char=" \Bool:=IsFile("TEMP:/renamed.txt" \CharSpec);
        TPWrite "device regular=" \Bool:=IsFile("TEMP:" \RegFile);
        RemoveFile "TEMP:/renamed.txt";
        TPWrite "removed=" \Bool:=NOT IsFile("TEMP:/renamed.txt");
        Open "HOME:/two.txt", f \Write;
        Close f;
        try "rename onto existing", 1;
        try "copy onto existing", 2;
        try "copy missing", 3;
        try "remove missing", 4;
        try "size of missing", 5;
        try "escape", 6;
        try "remove a folder", 7;
    ENDPROC

    PROC try(string what, num which)
        VAR num n;
        TEST which
        CASE 1:
            RenameFile "HOME:/one.txt", "HOME:/two.txt";
        CASE 2:
            CopyFile "HOME:/one.txt", "HOME:/two.txt";
        CASE 3:
            CopyFile "HOME:/none.txt", "HOME:/three.txt";
        CASE 4:
            RemoveFile "HOME:/none.txt";
        CASE 5:
            n := FileSize("HOME:/none.txt");
        CASE 6:
            n := FileSize("HOME:/a/../../../etc/hostname");
        CASE 7:
            MakeDir "HOME:/folder";
            RemoveFile "HOME:/folder";
        ENDTEST
        TPWrite what + ": no error";
    ERROR
        IF ERRNO = ERR_FILEEXIST THEN
            TPWrite what + ": ERR_FILEEXIST";
        ELSEIF ERRNO = ERR_FILEACC THEN
            TPWrite what + ": ERR_FILEACC";
        ENDIF
        RETURN;
    ENDPROC
ENDMODULE
