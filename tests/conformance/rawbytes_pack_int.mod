MODULE rawbytes_pack_int
    ! PackRawBytes \IntX (semantics 3.6): little-endian by default, big-endian
    ! with \Network; packing extends the valid length. 258 = 0x0102, so UINT
    ! little-endian gives the bytes 02 01 and \Network gives 01 02.
    PROC main()
        VAR rawbytes raw;
        VAR byte b;
        VAR num n;
        VAR dnum d;
        TPWrite "len0=" \Num:=RawBytesLen(raw);
        PackRawBytes 258, raw, 1 \IntX:=UINT;
        TPWrite "len1=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 1, b \Hex1;
        TPWrite "b1=" \Num:=b;
        UnpackRawBytes raw, 2, b \Hex1;
        TPWrite "b2=" \Num:=b;
        PackRawBytes 258, raw \Network, 3 \IntX:=UINT;
        TPWrite "len2=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 3, b \Hex1;
        TPWrite "b3=" \Num:=b;
        UnpackRawBytes raw, 4, b \Hex1;
        TPWrite "b4=" \Num:=b;
        ! Bytes 02 01 01 02: read back as UINT either way round.
        UnpackRawBytes raw, 1, n \IntX:=UINT;
        TPWrite "le=" \Num:=n;
        UnpackRawBytes raw \Network, 1, n \IntX:=UINT;
        TPWrite "be=" \Num:=n;
        ! -2 as INT is FE FF; unsigned it reads 65534, signed -2.
        PackRawBytes -2, raw, 5 \IntX:=INT;
        UnpackRawBytes raw, 5, n \IntX:=UINT;
        TPWrite "u=" \Num:=n;
        UnpackRawBytes raw, 5, n \IntX:=INT;
        TPWrite "s=" \Num:=n;
        ! A dnum with UDINT: 4294967295 is FF FF FF FF.
        d := 4294967295;
        PackRawBytes d, raw, 7 \IntX:=UDINT;
        TPWrite "len3=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 10, b \Hex1;
        TPWrite "b10=" \Num:=b;
        UnpackRawBytes raw, 7, n \IntX:=DINT;
        TPWrite "dint=" \Num:=n;
        ! Packing at 1 again overwrites without shrinking.
        PackRawBytes 200, raw, 1 \Hex1;
        TPWrite "len4=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 1, b \Hex1;
        TPWrite "b1=" \Num:=b;
    ENDPROC
ENDMODULE
