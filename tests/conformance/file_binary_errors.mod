MODULE file_binary_errors
    ! Error paths of the binary instructions: WriteBin with NChar beyond the array
    ! (ERR_OUTOFBND) or a number that is not a byte (ERR_ARGVALERR); ReadStrBin with a
    ! count outside 1..80 (ERR_ARGVALERR); WriteRawBytes with more bytes than are valid
    ! (ERR_OUTOFBND); binary writes to a file opened for reading and reads from one
    ! opened for writing (ERR_FILEACC). See docs/semantics.md for the choices.
    VAR iodev f;

    PROC main()
        Open "HOME:/b.bin", f \Write \Bin;
        WriteStrBin f, "abc";
        Close f;
        FOR i FROM 1 TO 7 DO
            try i;
        ENDFOR
    ENDPROC

    PROC try(num which)
        VAR num buf{3} := [1, 2, 300];
        VAR rawbytes raw;
        VAR string s;
        VAR num n;
        TEST which
        CASE 1:
            Open "HOME:/w.bin", f \Write \Bin;
            WriteBin f, buf, 4;
        CASE 2:
            Open "HOME:/w.bin", f \Write \Bin;
            WriteBin f, buf, 3;
        CASE 3:
            Open "HOME:/b.bin", f \Read \Bin;
            s := ReadStrBin(f, 81);
        CASE 4:
            Open "HOME:/w.bin", f \Write \Bin;
            PackRawBytes 1, raw, 1 \Hex1;
            WriteRawBytes f, raw \NoOfBytes:=2;
        CASE 5:
            Open "HOME:/b.bin", f \Read \Bin;
            WriteAnyBin f, 1;
        CASE 6:
            Open "HOME:/w.bin", f \Write \Bin;
            ReadAnyBin f, n;
        CASE 7:
            Open "HOME:/w.bin", f \Write \Bin;
            ReadRawBytes f, raw;
        ENDTEST
        TPWrite NumToStr(which, 0) + ": no error";
        Close f;
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            TPWrite NumToStr(which, 0) + ": ERR_OUTOFBND";
        ELSEIF ERRNO = ERR_ARGVALERR THEN
            TPWrite NumToStr(which, 0) + ": ERR_ARGVALERR";
        ELSEIF ERRNO = ERR_FILEACC THEN
            TPWrite NumToStr(which, 0) + ": ERR_FILEACC";
        ENDIF
        Close f;
        RETURN;
    ENDPROC
ENDMODULE
