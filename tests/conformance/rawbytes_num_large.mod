MODULE rawbytes_num_large
    ! Integers past 2^23 (8388608) in a num: the manual calls 0..8388608 a limitation for
    ! storage of integers in a num, not an error. Packing 16777216 (2^24, held exactly)
    ! as UDINT writes 00 00 00 01 (little-endian); unpacking FF FF FF FF into a num gives
    ! the nearest num, which equals the literal 4294967295 (the same nearest num). The
    ! num literal 4294967295 is 4294967296 and does not fit in a UDINT: ERR_ARGVALERR.
    VAR rawbytes rb;
    VAR num n;
    VAR dnum d;
    VAR byte b;

    PROC main()
        PackRawBytes 16777216, rb, 1 \IntX:=UDINT;
        UnpackRawBytes rb, 4, b \Hex1;
        TPWrite "byte 4 " \Num:=b;
        UnpackRawBytes rb, 1, d \IntX:=UDINT;
        TPWrite "dnum " \Dnum:=d;
        FOR i FROM 1 TO 4 DO
            PackRawBytes 255, rb, i \Hex1;
        ENDFOR
        UnpackRawBytes rb, 1, n \IntX:=UDINT;
        TPWrite "marker " \Bool:=n = 4294967295;
        PackRawBytes 4294967295, rb, 1 \IntX:=UDINT;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_ARGVALERR TPWrite "ERR_ARGVALERR";
        RETURN;
    ENDPROC
ENDMODULE
