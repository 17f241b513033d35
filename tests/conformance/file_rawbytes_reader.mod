MODULE file_rawbytes_reader
    ! A reader in the style of abb-motion-program-exec (docs/semantics.md): numbers
    ! stored as 4-byte floats are read through a rawbytes that ReadRawBytes refills
    ! (at most 1024 bytes at a time); the end of the file shows as ERR_RANYBIN_EOF,
    ! which the reader turns into FALSE with SkipWarn and TRYNEXT.
    VAR iodev f;
    VAR rawbytes buf;
    VAR num offset := 1;

    PROC main()
        VAR rawbytes out;
        VAR num v;
        VAR num count := 0;
        VAR num sum := 0;
        ! 300 floats: 256 fill one rawbytes, 44 more follow.
        Open "RAMDISK:/floats.bin", f \Write \Bin;
        FOR i FROM 1 TO 300 DO
            PackRawBytes i, out, 4 * ((i - 1) MOD 256) + 1 \Float4;
            IF i MOD 256 = 0 THEN
                WriteRawBytes f, out;
                ClearRawBytes out;
            ENDIF
        ENDFOR
        WriteRawBytes f, out;
        Close f;
        Open "RAMDISK:/floats.bin", f \Read \Bin;
        WHILE next_num(v) DO
            count := count + 1;
            sum := sum + v;
        ENDWHILE
        Close f;
        TPWrite "count=" \Num:=count;
        TPWrite "sum=" \Num:=sum;
    ENDPROC

    FUNC bool fill()
        IF RawBytesLen(buf) = 0 OR offset > RawBytesLen(buf) THEN
            ClearRawBytes buf;
            offset := 1;
            ReadRawBytes f, buf;
            IF RawBytesLen(buf) = 0 RETURN FALSE;
        ENDIF
        RETURN TRUE;
    ERROR
        IF ERRNO = ERR_RANYBIN_EOF THEN
            SkipWarn;
            TRYNEXT;
        ENDIF
    ENDFUNC

    FUNC bool next_num(INOUT num v)
        IF NOT fill() RETURN FALSE;
        UnpackRawBytes buf, offset, v \Float4;
        offset := offset + 4;
        RETURN TRUE;
    ENDFUNC
ENDMODULE
