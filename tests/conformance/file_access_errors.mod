MODULE file_access_errors
    ! Where Open raises ERR_FILEOPEN (a file that cannot be opened: missing for \Read,
    ! a path that leaves its device, a serial channel the virtual controller has not, an
    ! iodev already open) and where reading and writing raise ERR_FILEACC (a file opened
    ! the other way, an iodev that is closed or was never opened).
    VAR iodev f;

    PROC main()
        try_open "HOME:/missing.txt";
        try_open "HOME:/../outside.txt";
        try_open "/etc/hostname";
        try_open "com1:";
        try_open "NODEVICE:/x.txt";
        open_twice;
        read_write_only;
        write_read_only;
        use_closed;
        use_never_opened;
    ENDPROC

    PROC try_open(string path)
        Open path, f \Read;
        TPWrite "opened " + path;
        Close f;
    ERROR
        IF ERRNO = ERR_FILEOPEN TPWrite path + ": ERR_FILEOPEN";
        RETURN;
    ENDPROC

    PROC open_twice()
        Open "HOME:/a.txt", f \Write;
        Open "HOME:/b.txt", f \Write;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEOPEN TPWrite "open twice: ERR_FILEOPEN";
        Close f;
        RETURN;
    ENDPROC

    PROC read_write_only()
        VAR string s;
        Open "HOME:/a.txt", f \Write;
        s := ReadStr(f);
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite "read from \\Write: ERR_FILEACC";
        Close f;
        RETURN;
    ENDPROC

    PROC write_read_only()
        Open "HOME:/a.txt", f \Read;
        Write f, "x";
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite "write to \\Read: ERR_FILEACC";
        Close f;
        RETURN;
    ENDPROC

    PROC use_closed()
        Open "HOME:/a.txt", f \Write;
        Close f;
        ! Closing again does nothing.
        Close f;
        Write f, "x";
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite "write after Close: ERR_FILEACC";
        RETURN;
    ENDPROC

    PROC use_never_opened()
        VAR iodev g;
        VAR num n;
        n := ReadBin(g);
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILEACC TPWrite "never opened: ERR_FILEACC";
        RETURN;
    ENDPROC
ENDMODULE
