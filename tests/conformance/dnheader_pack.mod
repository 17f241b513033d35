MODULE dnheader_pack
    ! PackDNHeader (ABB's RAPID reference manual, "Format DeviceNet Header"): byte 1 is
    ! the controller's internal DeviceNet code (its value is not public, so it is not
    ! printed), byte 2 the service (two hex digits), byte 3 the path's length, then the
    ! path's characters as written. RawData is cleared first; the message data goes at
    ! RawBytesLen + 1. A service that is not two hex digits raises ERR_ARGVALERR
    ! (docs/semantics.md) and leaves RawData as it was.
    PROC main()
        VAR rawbytes raw;
        VAR num n;
        VAR string s;
        PackRawBytes "0123456789012345678901234567890", raw, 1 \ASCII;
        TPWrite "before=" \Num:=RawBytesLen(raw);
        PackDNHeader "0E", "6,20 01 24 01 30 06,9,4", raw;
        TPWrite "len=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 2, n \IntX:=USINT;
        TPWrite "service=" \Num:=n;
        UnpackRawBytes raw, 3, n \IntX:=USINT;
        TPWrite "size=" \Num:=n;
        UnpackRawBytes raw, 4, s \ASCII:=n;
        TPWrite "path=" + s;
        PackDNHeader "10", "20 1D 24 01 30 64", raw;
        TPWrite "len=" \Num:=RawBytesLen(raw);
        PackRawBytes 100, raw, RawBytesLen(raw) + 1 \IntX:=UINT;
        TPWrite "with data=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 21, n \IntX:=UINT;
        TPWrite "data=" \Num:=n;
        PackDNHeader "1f", "", raw;
        UnpackRawBytes raw, 2, n \IntX:=USINT;
        TPWrite "service=" \Num:=n;
        TPWrite "len=" \Num:=RawBytesLen(raw);
        TPWrite "E: " + pack("E", raw);
        TPWrite "0G: " + pack("0G", raw);
        TPWrite "len=" \Num:=RawBytesLen(raw);
    ENDPROC

    FUNC string pack(string service, VAR rawbytes raw)
        PackDNHeader service, "20 01", raw;
        RETURN "ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    ENDFUNC
ENDMODULE
