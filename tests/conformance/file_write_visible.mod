MODULE file_write_visible
    ! What Write wrote is in the file for anything that looks at it next, even before
    ! Close: FileSize, a second iodev reading it, and the writer after Rewind.
    ! Write ends each line with a newline (manual, Write), so "abc" is 4 bytes.
    VAR iodev writer;
    VAR iodev reader;

    PROC main()
        Open "HOME:/v.txt", writer \Write;
        Write writer, "abc";
        TPWrite "size " \Num:=FileSize("HOME:/v.txt");
        Open "HOME:/v.txt", reader \Read;
        TPWrite "read " + ReadStr(reader);
        Close reader;
        Write writer, "de";
        Close writer;
        TPWrite "size after close " \Num:=FileSize("HOME:/v.txt");
    ENDPROC
ENDMODULE
