MODULE bits_byte_ops
    ! Bit functions on bytes (semantics 3.2): values 0..255, bit positions 1..8
    ! with 1 the least significant bit; shifted-out bits are lost.
    VAR byte data1 := 38;
    VAR byte data2 := 34;

    PROC main()
        VAR byte b;
        VAR num i;
        VAR string bits;
        ! 38 = 00100110, 34 = 00100010
        TPWrite "and=" \Num:=BitAnd(data1, data2);
        TPWrite "or=" \Num:=BitOr(data1, data2);
        TPWrite "xor=" \Num:=BitXOr(data1, data2);
        TPWrite "neg=" \Num:=BitNeg(data1);
        ! 38 << 3 = 304, only 00110000 = 48 stays; all 8 steps clear it
        TPWrite "lsh=" \Num:=BitLSh(data1, 3);
        TPWrite "rsh=" \Num:=BitRSh(data1, 2);
        TPWrite "lsh8=" \Num:=BitLSh(255, 8);
        TPWrite "rsh8=" \Num:=BitRSh(255, 8);
        TPWrite "chk2=" \Bool:=BitCheck(data1, 2);
        TPWrite "chk1=" \Bool:=BitCheck(data1, 1);
        b := 0;
        BitSet b, 1;
        BitSet b, 8;
        TPWrite "set=" \Num:=b;
        BitSet b, 8;
        TPWrite "again=" \Num:=b;
        BitClear b, 1;
        TPWrite "clear=" \Num:=b;
        BitClear b, 2;
        TPWrite "clear0=" \Num:=b;
        ! bit pattern of 38, most significant bit first
        bits := "";
        FOR i FROM 8 TO 1 STEP -1 DO
            IF BitCheck(data1, i) THEN
                bits := bits + "1";
            ELSE
                bits := bits + "0";
            ENDIF
        ENDFOR
        TPWrite bits;
    ENDPROC
ENDMODULE
