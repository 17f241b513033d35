MODULE file_sizes
    ! FSSize (manual): the total or free space of the file system holding a file, in
    ! bytes, or divided by 1024 (\Kbyte) or 1048576 (\Mbyte). A size beyond the largest
    ! integer a num holds exactly (8388608) raises ERR_FILESIZE, as FileSize does for a
    ! file larger than that.
    PROC main()
        VAR num total;
        VAR num free;
        VAR iodev f;
        VAR rawbytes raw;
        total := FSSize("HOME:" \Total \Mbyte);
        free := FSSize("HOME:" \Free \Mbyte);
        TPWrite "total>0=" \Bool:=(total > 0);
        TPWrite "free<=total=" \Bool:=(free <= total);
        ! A file of 8193 * 1024 bytes: one KiB beyond 8388608 bytes.
        PackRawBytes 0, raw, 1024 \Hex1;
        Open "TEMP:/big.bin", f \Write \Bin;
        FOR i FROM 1 TO 8193 DO
            WriteRawBytes f, raw;
        ENDFOR
        Close f;
        TPWrite "size=" \Num:=FileSize("TEMP:/big.bin") DIV 1024;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_FILESIZE THEN
            TPWrite "big file: ERR_FILESIZE";
            RemoveFile "TEMP:/big.bin";
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
