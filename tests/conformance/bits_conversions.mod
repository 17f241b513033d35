MODULE bits_conversions
    ! ByteToStr / StrToByte forms (semantics 3.1): decimal "0".."255", \Hex "00".."FF",
    ! \Okt "000".."377", \Bin "00000000".."11111111", \Char one character.
    ! DecToHex / HexToDec convert digit strings; hex output is uppercase.
    PROC main()
        VAR byte b := 10;
        TPWrite ByteToStr(b);
        TPWrite ByteToStr(b \Hex);
        TPWrite ByteToStr(b \Okt);
        TPWrite ByteToStr(b \Bin);
        TPWrite ByteToStr(65 \Char);
        TPWrite ByteToStr(255 \Hex) + " " + ByteToStr(255 \Okt) + " " + ByteToStr(255 \Bin);
        TPWrite ByteToStr(0 \Hex) + " " + ByteToStr(0 \Okt) + " " + ByteToStr(0);
        TPWrite "dec=" \Num:=StrToByte("200");
        TPWrite "hex=" \Num:=StrToByte("FF" \Hex);
        TPWrite "okt=" \Num:=StrToByte("377" \Okt);
        TPWrite "bin=" \Num:=StrToByte("00001010" \Bin);
        TPWrite "chr=" \Num:=StrToByte("a" \Char);
        TPWrite "round=" \Num:=StrToByte(ByteToStr(173 \Bin) \Bin);
        TPWrite DecToHex("99999999");
        TPWrite HexToDec("5F5E0FF");
        TPWrite DecToHex("255") + " " + DecToHex("0") + " " + HexToDec("10");
        TPWrite DecToHex("9223372036854775807");
        TPWrite HexToDec("7FFFFFFFFFFFFFFF");
    ENDPROC
ENDMODULE
