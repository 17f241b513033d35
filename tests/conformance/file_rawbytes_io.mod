MODULE file_rawbytes_io
    ! WriteRawBytes writes the valid bytes of a rawbytes (or the first \NoOfBytes);
    ! ReadRawBytes fills a rawbytes from index 1 with the next bytes of the file, at most
    ! 1024 (a rawbytes' size), and at end of file raises ERR_RANYBIN_EOF (as
    ! abb-motion-program-exec relies on, docs/semantics.md).
    VAR iodev f;
    VAR rawbytes raw;

    PROC main()
        VAR num chunks := 0;
        VAR num total := 0;
        VAR num v;
        ! 1024 + 1024 + 3 bytes.
        ClearRawBytes raw;
        FOR i FROM 1 TO 256 DO
            PackRawBytes i, raw, 4 * i - 3 \IntX:=UDINT;
        ENDFOR
        Open "HOME:/raw.bin", f \Write \Bin;
        WriteRawBytes f, raw;
        WriteRawBytes f, raw;
        WriteRawBytes f, raw \NoOfBytes:=3;
        Close f;
        TPWrite "size=" \Num:=FileSize("HOME:/raw.bin");
        Open "HOME:/raw.bin", f \Read \Bin;
        WHILE read_chunk() DO
            chunks := chunks + 1;
            total := total + RawBytesLen(raw);
            TPWrite "chunk " \Num:=RawBytesLen(raw);
        ENDWHILE
        TPWrite "chunks=" \Num:=chunks;
        TPWrite "total=" \Num:=total;
        Rewind f;
        ReadRawBytes f, raw;
        UnpackRawBytes raw, 1021, v \IntX:=UDINT;
        TPWrite "last int of chunk 1=" \Num:=v;
        Close f;
    ENDPROC

    FUNC bool read_chunk()
        ReadRawBytes f, raw;
        RETURN TRUE;
    ERROR
        IF ERRNO = ERR_RANYBIN_EOF THEN
            TPWrite "ERR_RANYBIN_EOF, length " \Num:=RawBytesLen(raw);
            RETURN FALSE;
        ENDIF
    ENDFUNC
ENDMODULE
