MODULE rawbytes_float_ascii
    ! \Float4 stores an IEEE single, \ASCII the characters of a string or a
    ! byte as its character (semantics 3.6). 1.0 as a single is 3F800000, so
    ! little-endian its first byte is 00 and its last 3F (63); with \Network
    ! the order is reversed.
    PROC main()
        VAR rawbytes raw;
        VAR byte b;
        VAR num f;
        VAR string s;
        PackRawBytes 1, raw, 1 \Float4;
        UnpackRawBytes raw, 1, b \Hex1;
        TPWrite "f1=" \Num:=b;
        UnpackRawBytes raw, 4, b \Hex1;
        TPWrite "f4=" \Num:=b;
        PackRawBytes -2.5, raw \Network, 5 \Float4;
        UnpackRawBytes raw, 5, b \Hex1;
        TPWrite "g1=" \Num:=b;
        UnpackRawBytes raw \Network, 5, f \Float4;
        TPWrite "g=" \Num:=f * 2;
        UnpackRawBytes raw, 1, f \Float4;
        TPWrite "f=" \Num:=f;
        TPWrite "len=" \Num:=RawBytesLen(raw);
        PackRawBytes "Hello", raw, 9 \ASCII;
        PackRawBytes 33, raw, 14 \ASCII;
        TPWrite "len=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 9, s \ASCII:=6;
        TPWrite "s=" + s;
        UnpackRawBytes raw, 10, s \ASCII:=3;
        TPWrite "part=" + s;
        UnpackRawBytes raw, 9, b \ASCII:=1;
        TPWrite "H=" \Num:=b;
    ENDPROC
ENDMODULE
