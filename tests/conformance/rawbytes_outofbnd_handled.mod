MODULE rawbytes_outofbnd_handled
    ! Unpacking past the valid bytes, or an index outside 1..1024, raises
    ! ERR_OUTOFBND (semantics 3.6; the same error as an array index out of
    ! bounds). A value that does not fit the integer type raises ERR_ARGVALERR.
    PROC main()
        VAR rawbytes raw;
        VAR num n := -1;
        VAR num outofbnd := 0;
        VAR num argval := 0;
        PackRawBytes 7, raw, 1 \IntX:=UINT;
        UnpackRawBytes raw, 2, n \IntX:=UINT;
        TPWrite "n=" \Num:=n;
        UnpackRawBytes raw, 0, n \Hex1;
        PackRawBytes 1, raw, 1025 \Hex1;
        PackRawBytes 1, raw, 1022 \IntX:=UDINT;
        PackRawBytes 256, raw, 1 \IntX:=USINT;
        PackRawBytes -1, raw, 1 \IntX:=UINT;
        TPWrite "len=" \Num:=RawBytesLen(raw);
        UnpackRawBytes raw, 1, n \IntX:=UINT;
        TPWrite "n=" \Num:=n;
        TPWrite "outofbnd=" \Num:=outofbnd;
        TPWrite "argval=" \Num:=argval;
    ERROR
        IF ERRNO = ERR_OUTOFBND THEN
            outofbnd := outofbnd + 1;
            TRYNEXT;
        ELSEIF ERRNO = ERR_ARGVALERR THEN
            argval := argval + 1;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
