MODULE binary_file_anybin
    ! Saves and restores the taught layout of a pallet pattern in a
    ! binary file, so it survives a reinstallation of the program.
    ! WriteAnyBin/ReadAnyBin store whole RAPID values, the raw
    ! functions are used for a header with a magic number.

    RECORD layout_header
        num version;
        num rows;
        num cols;
        string name;
    ENDRECORD

    VAR iodev ioBin;
    VAR layout_header lhCurrent:=[3,4,5,"EUR-1200x800"];
    VAR robtarget pLayout{20};
    VAR rawbytes rbMagic;
    VAR num nBytes{4}:=[82,65,80,73];
    CONST string FILE_NAME:="layout.bin";

    PROC main()
        FOR i FROM 1 TO Dim(pLayout,1) DO
            pLayout{i}:=[[(i-1) MOD 5*240,(i-1) DIV 5*200,0],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
        ENDFOR
        save_layout;
        load_layout;
    ENDPROC

    PROC save_layout()
        Open "HOME:"\File:=FILE_NAME,ioBin\Write\Bin;
        ! Magic number "RAPI" as plain bytes
        WriteBin ioBin,nBytes,4;
        ClearRawBytes rbMagic;
        PackRawBytes lhCurrent.version,rbMagic,1\IntX:=UDINT;
        WriteRawBytes ioBin,rbMagic\NoOfBytes:=4;
        WriteStrBin ioBin,"LAYOUT";
        WriteAnyBin ioBin,lhCurrent;
        WriteAnyBin ioBin,pLayout;
        Close ioBin;
    ERROR
        IF ERRNO=ERR_FILEOPEN THEN
            TPWrite "Cannot write "+FILE_NAME;
            RETURN;
        ENDIF
        Close ioBin;
        RAISE;
    ENDPROC

    PROC load_layout()
        VAR num nByte;
        VAR num nVersion;
        VAR string sTag;
        Open "HOME:"\File:=FILE_NAME,ioBin\Read\Bin;
        FOR i FROM 1 TO 4 DO
            nByte:=read_byte(ioBin\MaxTime:=1);
            IF nByte=EOF_BIN THEN
                TPWrite "File too short";
                Close ioBin;
                RETURN;
            ENDIF
        ENDFOR
        ClearRawBytes rbMagic;
        ReadRawBytes ioBin,rbMagic\Time:=1;
        UnpackRawBytes rbMagic,1,nVersion\IntX:=UDINT;
        sTag:=ReadStrBin(ioBin,6\Time:=1);
        IF sTag<>"LAYOUT" OR nVersion<>3 THEN
            TPWrite "Unknown layout file format "+sTag;
            Close ioBin;
            RETURN;
        ENDIF
        ReadAnyBin ioBin,lhCurrent;
        ReadAnyBin ioBin,pLayout\Time:=5;
        Close ioBin;
        TPWrite "Layout "+lhCurrent.name+" version "\Num:=lhCurrent.version;
    ERROR
        TEST ERRNO
        CASE ERR_FILEOPEN:
            TPWrite "No saved layout";
            RETURN;
        CASE ERR_RANYBIN_CHK,ERR_RANYBIN_EOF:
            TPWrite "Layout file is corrupt";
            Close ioBin;
            RETURN;
        CASE ERR_DEV_MAXTIME:
            Close ioBin;
            RETURN;
        ENDTEST
        RAISE;
    ENDPROC

    ! The timeout is only passed on to ReadBin when the caller gave one
    FUNC num read_byte(VAR iodev dev\num MaxTime)
        RETURN ReadBin(dev\Time?MaxTime);
    ENDFUNC

ENDMODULE
