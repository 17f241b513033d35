MODULE file_open_modes
    ! Open (manual Open): \Write empties the file, \Append writes at its end, and Open
    ! without \Read, \Write or \Append acts like \Write for a character-based file and,
    ! with \Bin, opens for reading and writing at the end of the file. \File gives the
    ! file name apart from the device. Rewind goes back to the start.
    PROC main()
        VAR iodev f;
        Open "HOME:" \File:="m.txt", f \Write;
        Write f, "one";
        Close f;
        Open "HOME:/m.txt", f \Append;
        Write f, "two";
        Close f;
        show "after append";
        Open "HOME:/m.txt", f \Write;
        Write f, "three";
        Close f;
        show "after write";
        Open "HOME:/m.txt", f;
        Write f, "four";
        Close f;
        show "after plain open";
        Open "HOME:/m.bin", f \Bin;
        WriteStrBin f, "xy";
        Close f;
        Open "HOME:/m.bin", f \Bin;
        WriteStrBin f, "z";
        Rewind f;
        TPWrite "bin=" + ReadStrBin(f, 10);
        Close f;
    ENDPROC

    PROC show(string title)
        VAR iodev g;
        VAR string s;
        TPWrite title + ":";
        Open "HOME:/m.txt", g \Read;
        s := ReadStr(g);
        WHILE s <> EOF DO
            TPWrite "  " + s;
            s := ReadStr(g);
        ENDWHILE
        Rewind g;
        TPWrite "  again " + ReadStr(g);
        Close g;
    ENDPROC
ENDMODULE
