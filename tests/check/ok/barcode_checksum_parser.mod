MODULE barcode_checksum_parser
    ! Parses the DataMatrix code read by the camera on the infeed.
    ! Format:  <variant 2 digits>|<serial 8 digits>|<date YYMMDD>|<check 2 hex>
    ! Example: 07|00418734|210714|5C
    ! The check value is the XOR of all characters before the last '|'.

    RECORD code_fields
        num variant;
        string serial;
        string date_code;
        bool valid;
    ENDRECORD

    VAR code_fields cfLast;
    VAR num nBadCodes:=0;
    CONST string SEP:="|";

    PROC main()
        cfLast:=parse_code("07|00418734|210714|5C");
        IF cfLast.valid THEN
            TPWrite "Variant "\Num:=cfLast.variant;
            TPWrite "Serial  "+cfLast.serial;
        ELSE
            nBadCodes:=nBadCodes+1;
        ENDIF
        TPWrite "Serial as hex: "+DecToHex(cfLast.serial);
        TPWrite "Back to dec:   "+HexToDec(DecToHex(cfLast.serial));
    ENDPROC

    FUNC code_fields parse_code(string raw)
        VAR code_fields cf;
        VAR num p1;
        VAR num p2;
        VAR num p3;
        VAR string sCheck;
        VAR num nVariant;

        cf.valid:=FALSE;
        p1:=StrFind(raw,1,SEP);
        p2:=StrFind(raw,p1+1,SEP);
        p3:=StrFind(raw,p2+1,SEP);
        IF p3>StrLen(raw) RETURN cf;

        IF NOT StrToVal(StrPart(raw,1,p1-1),nVariant) RETURN cf;
        cf.variant:=nVariant;
        cf.serial:=StrPart(raw,p1+1,p2-p1-1);
        cf.date_code:=StrPart(raw,p2+1,p3-p2-1);
        sCheck:=StrPart(raw,p3+1,StrLen(raw)-p3);

        IF StrLen(cf.serial)<>8 OR StrLen(cf.date_code)<>6 RETURN cf;
        IF StrFind(cf.serial,1,STR_DIGIT\NotInSet)<=StrLen(cf.serial) RETURN cf;
        cf.valid:=xor_checksum(StrPart(raw,1,p3-1))=StrToByte(sCheck\Hex);
        RETURN cf;
    ERROR
        ! Malformed code (for example StrPart out of range)
        nBadCodes:=nBadCodes+1;
        cf.valid:=FALSE;
        RETURN cf;
    ENDFUNC

    ! XOR of all character codes of the text
    FUNC byte xor_checksum(string text)
        VAR byte bSum:=0;
        VAR byte bChar;
        FOR i FROM 1 TO StrLen(text) DO
            bChar:=StrToByte(StrPart(text,i,1)\Char);
            bSum:=BitXOr(bSum,bChar);
        ENDFOR
        RETURN bSum;
    ENDFUNC

    ! Checksum as two hex digits, zero padded
    FUNC string checksum_text(string text)
        VAR string sHex;
        sHex:=ByteToStr(xor_checksum(text)\Hex);
        IF StrLen(sHex)<2 sHex:="0"+sHex;
        RETURN sHex;
    ENDFUNC

    ! Printable representation of a character code
    FUNC string char_of(byte code)
        IF code<32 OR code>126 THEN
            RETURN "<"+ByteToStr(code)+">";
        ENDIF
        RETURN ByteToStr(code\Char);
    ENDFUNC

ENDMODULE
