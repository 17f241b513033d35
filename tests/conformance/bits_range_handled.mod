MODULE bits_range_handled
    ! Arguments outside the documented ranges (byte 0..255, bit position 1..8 or
    ! 1..52, shift steps 1..8, well-formed digit text) are run-time errors. The manual
    ! does not name the errno, so only the recovery is checked, not the error name.
    VAR num fails := 0;

    PROC main()
        VAR byte b;
        VAR dnum d;
        VAR bool t;
        VAR string s;
        b := BitAnd(256, 1);
        t := BitCheck(1, 9);
        t := BitCheck(1, 0);
        b := BitLSh(1, 9);
        BitSet b, 9;
        t := BitCheckDnum(1, 53);
        d := BitAndDnum(-1, 1);
        b := StrToByte("256");
        b := StrToByte("1G" \Hex);
        b := StrToByte("12" \Bin);
        s := DecToHex("1A");
        s := HexToDec("XYZ");
        TPWrite "fails=" \Num:=fails;
        b := 5;
        BitSet b, 8;
        TPWrite "b=" \Num:=b;
    ERROR
        fails := fails + 1;
        TRYNEXT;
    ENDPROC
ENDMODULE
