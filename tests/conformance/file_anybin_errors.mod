MODULE file_anybin_errors
    ! ReadAnyBin raises ERR_RANYBIN_CHK when the data read is corrupt (checksum error,
    ! manual ReadAnyBin) and ERR_RANYBIN_EOF when the file ends in the middle of a value.
    ! Data of another type than the one written is reported as corrupt too (our choice,
    ! see docs/semantics.md).
    VAR iodev f;

    PROC main()
        VAR num n;
        VAR string s;
        ! Bytes that WriteAnyBin did not write.
        Open "HOME:/junk.bin", f \Write \Bin;
        WriteStrBin f, "not a value";
        Close f;
        read_num "HOME:/junk.bin";
        ! A string where a num is read.
        Open "HOME:/str.bin", f \Write \Bin;
        WriteAnyBin f, "text";
        Close f;
        read_num "HOME:/str.bin";
        ! A value cut short: the first two bytes only.
        Open "HOME:/cut.bin", f \Write \Bin;
        WriteAnyBin f, 5;
        Close f;
        Open "HOME:/cut.bin", f \Read \Bin;
        s := ReadStrBin(f, 2);
        Close f;
        Open "HOME:/short.bin", f \Write \Bin;
        WriteStrBin f, s;
        Close f;
        read_num "HOME:/short.bin";
        ! An empty file.
        Open "HOME:/empty.bin", f \Write \Bin;
        Close f;
        read_num "HOME:/empty.bin";
    ENDPROC

    PROC read_num(string path)
        VAR num n;
        Open path, f \Read \Bin;
        ReadAnyBin f, n;
        TPWrite "read " \Num:=n;
        Close f;
    ERROR
        IF ERRNO = ERR_RANYBIN_CHK THEN
            TPWrite path + ": ERR_RANYBIN_CHK";
        ELSEIF ERRNO = ERR_RANYBIN_EOF THEN
            TPWrite path + ": ERR_RANYBIN_EOF";
        ENDIF
        Close f;
        RETURN;
    ENDPROC
ENDMODULE
