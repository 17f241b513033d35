MODULE rawbytes_clear_copy
    ! ClearRawBytes zeroes from FromIndex (default 1) and sets the valid length
    ! to FromIndex - 1; CopyRawBytes copies NoOfBytes (default all valid bytes
    ! from FromIndex) and extends the destination's valid length (semantics 3.6).
    PROC main()
        VAR rawbytes a;
        VAR rawbytes c;
        VAR byte b;
        VAR num i;
        FOR i FROM 1 TO 6 DO
            PackRawBytes i * 10, a, i \Hex1;
        ENDFOR
        TPWrite "a=" \Num:=RawBytesLen(a);
        CopyRawBytes a, 2, c, 1 \NoOfBytes:=3;
        TPWrite "c=" \Num:=RawBytesLen(c);
        UnpackRawBytes c, 3, b \Hex1;
        TPWrite "c3=" \Num:=b;
        CopyRawBytes a, 5, c, 3;
        TPWrite "c=" \Num:=RawBytesLen(c);
        UnpackRawBytes c, 3, b \Hex1;
        TPWrite "c3=" \Num:=b;
        UnpackRawBytes c, 4, b \Hex1;
        TPWrite "c4=" \Num:=b;
        ClearRawBytes a \FromIndex:=4;
        TPWrite "a=" \Num:=RawBytesLen(a);
        UnpackRawBytes a, 3, b \Hex1;
        TPWrite "a3=" \Num:=b;
        ! Packing at 6 again leaves zeros at 4 and 5.
        PackRawBytes 99, a, 6 \Hex1;
        TPWrite "a=" \Num:=RawBytesLen(a);
        UnpackRawBytes a, 4, b \Hex1;
        TPWrite "a4=" \Num:=b;
        ClearRawBytes a;
        TPWrite "a=" \Num:=RawBytesLen(a);
        ! Copying a rawbytes is a copy of its bytes: c is unchanged.
        TPWrite "c=" \Num:=RawBytesLen(c);
    ENDPROC
ENDMODULE
