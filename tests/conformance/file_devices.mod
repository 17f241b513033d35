MODULE file_devices
    ! The devices HOME:, TEMP:, RAMDISK: and BACKUP: are separate folders; device names
    ! and file names are not case-sensitive; a path without a device is on HOME:; `.` and
    ! `..` inside a device are allowed as long as they stay in it (docs/semantics.md).
    PROC main()
        VAR iodev f;
        put "HOME:/same.txt", "home";
        put "TEMP:/same.txt", "temp";
        put "RAMDISK:/same.txt", "ramdisk";
        put "BACKUP:/same.txt", "backup";
        show "HOME:/same.txt";
        show "TEMP:/same.txt";
        show "RAMDISK:/same.txt";
        show "BACKUP:/same.txt";
        show "home:same.txt";
        show "same.txt";
        MakeDir "RAMDISK:/d";
        show "RAMDISK:/d/../same.txt";
        show "RAMDISK:/./d/./../same.txt";
        put "HOME:/Mixed.txt", "mixed";
        show "HOME:/MIXED.TXT";
        put "rel.txt", "relative";
        show "HOME:/rel.txt";
        TPWrite "escape=" \Bool:=escape();
    ENDPROC

    PROC put(string path, string text)
        VAR iodev f;
        Open path, f \Write;
        Write f, text;
        Close f;
    ENDPROC

    PROC show(string path)
        VAR iodev f;
        Open path, f \Read;
        TPWrite path + " -> " + ReadStr(f);
        Close f;
    ENDPROC

    FUNC bool escape()
        RETURN IsFile("RAMDISK:/d/../../HOME/same.txt");
    ERROR
        IF ERRNO = ERR_FILEACC RETURN FALSE;
    ENDFUNC
ENDMODULE
