MODULE bits_dnum_ops
    ! Bit functions on dnum (semantics 3.2): unsigned integers up to 2^52-1,
    ! bit positions 1..52; \Size limits BitNegDnum and BitLShDnum to that many bits.
    PROC main()
        VAR dnum d;
        VAR dnum all := 4503599627370495;
        TPWrite "and=" \Dnum:=BitAndDnum(4294967295, 65280);
        TPWrite "or=" \Dnum:=BitOrDnum(65536, 255);
        TPWrite "xor=" \Dnum:=BitXOrDnum(65535, 255);
        ! without \Size the complement spans all 52 bits
        TPWrite "neg8=" \Dnum:=BitNegDnum(38 \Size:=8);
        TPWrite "neg16=" \Dnum:=BitNegDnum(0 \Size:=16);
        TPWrite "negall=" \Bool:=BitNegDnum(38) = all - 38;
        TPWrite "negmax=" \Dnum:=BitNegDnum(all);
        TPWrite "lsh=" \Dnum:=BitLShDnum(1, 20);
        TPWrite "lsh8=" \Dnum:=BitLShDnum(200, 1 \Size:=8);
        TPWrite "lsh52=" \Dnum:=BitLShDnum(all, 52);
        TPWrite "rsh=" \Dnum:=BitRShDnum(1048576, 10);
        TPWrite "rsh52=" \Dnum:=BitRShDnum(all, 51);
        TPWrite "chk40=" \Bool:=BitCheckDnum(1099511627776, 41);
        TPWrite "chk39=" \Bool:=BitCheckDnum(1099511627776, 40);
        d := 0;
        BitSet d, 52;
        TPWrite "set52=" \Bool:=d = 2251799813685248;
        BitSet d, 1;
        BitClear d, 52;
        TPWrite "clear=" \Dnum:=d;
    ENDPROC
ENDMODULE
