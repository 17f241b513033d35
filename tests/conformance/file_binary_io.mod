MODULE file_binary_io
    ! WriteBin writes the first NChar numbers of an array as bytes, WriteStrBin the
    ! characters of a string; ReadBin reads one byte (EOF_BIN at end of file) and
    ! ReadStrBin NoOfChars characters (the string EOF at end of file) (manual).
    PROC main()
        VAR iodev f;
        VAR num buf{4} := [72, 105, 0, 255];
        VAR num b;
        VAR num count := 0;
        VAR num sum := 0;
        Open "HOME:/data.bin", f \Write \Bin;
        WriteBin f, buf, 2;
        WriteStrBin f, "ABC\0A";
        WriteBin f, buf, 4;
        Close f;
        Open "HOME:/data.bin", f \Read \Bin;
        TPWrite ReadStrBin(f, 2);
        b := ReadBin(f);
        TPWrite "A=" \Num:=b;
        TPWrite "[" + ReadStrBin(f, 2) + "]";
        ! The rest: the line feed (10), then 72, 105, 0, 255.
        b := ReadBin(f);
        WHILE b <> EOF_BIN DO
            count := count + 1;
            sum := sum + b;
            b := ReadBin(f);
        ENDWHILE
        TPWrite "count=" \Num:=count;
        TPWrite "sum=" \Num:=sum;
        TPWrite "str at end=" + ReadStrBin(f, 5);
        TPWrite "eof=" \Bool:=(ReadBin(f) = EOF_BIN);
        Close f;
    ENDPROC
ENDMODULE
