MODULE dnum_counters_bit_literals
    ! Lifetime counters of the press line are kept as dnum because
    ! they pass the exact integer range of num (8388608).
    ! Status words from the PLC are decoded with the bit functions.
    ! Numeric literals in hex (0x), octal (0o) and binary (0b) form.

    PERS dnum dnStrokesTotal:=12884901888;
    PERS dnum dnStrokesSinceService:=0;
    CONST dnum DN_SERVICE_INTERVAL:=5000000;
    CONST dnum DN_ZERO:=0;
    CONST dnum DN_ONE:=1;
    CONST dnum DN_THOUSAND:=1000;
    CONST num MASK_LOW_NIBBLE:=0x0F;
    CONST num MASK_ALL:=0XFF;
    CONST num PERM_BITS:=0o17;
    CONST num READY_PATTERN:=0b1011;
    CONST num BIG_HEX:=0x7FFF;

    VAR byte bStatus:=0b00000000;
    VAR byte bCommand:=0;
    VAR dnum dnFlags:=0;
    VAR num nErrCode:=0;

    PROC main()
        count_stroke;
        decode_status 0xA3;
        build_command TRUE,FALSE,TRUE;
        TPWrite "Strokes total: "\Dnum:=dnStrokesTotal;
        TPWrite "Strokes (num, thousands): "\Num:=strokes_in_thousands();
        TPWrite "As text: "+DnumToStr(dnStrokesTotal,0);
        TPWrite "Octal perm bits: "\Num:=PERM_BITS;
        TPWrite "Big hex: "\Num:=BIG_HEX;
    ENDPROC

    PROC count_stroke()
        dnStrokesTotal:=dnStrokesTotal+DN_ONE;
        dnStrokesSinceService:=dnStrokesSinceService+DN_ONE;
        IF dnStrokesSinceService>=DN_SERVICE_INTERVAL THEN
            TPWrite "Press service is due";
            dnStrokesSinceService:=DN_ZERO;
        ENDIF
    ENDPROC

    FUNC num strokes_in_thousands()
        VAR dnum dnK;
        dnK:=dnStrokesTotal DIV DN_THOUSAND;
        ! DnumToNum fails if the value does not fit into a num
        RETURN DnumToNum(dnK);
    ERROR
        IF ERRNO=ERR_ARGVALERR OR ERRNO=ERR_NUM_LIMIT THEN
            RETURN -1;
        ENDIF
        RAISE;
    ENDFUNC

    ! Status byte from the PLC: bit 1 ready, bit 2 busy, bit 8 fault,
    ! bits 5..7 hold an error code
    PROC decode_status(byte status)
        bStatus:=status;
        IF BitCheck(bStatus,8) THEN
            nErrCode:=BitAnd(BitRSh(bStatus,4),0b0111);
            TPWrite "PLC fault, code "\Num:=nErrCode;
        ENDIF
        IF BitAnd(bStatus,MASK_LOW_NIBBLE)=READY_PATTERN THEN
            TPWrite "PLC ready pattern";
        ENDIF
        TPWrite "Inverted status: "\Num:=BitNeg(bStatus);
        TPWrite "Masked: "\Num:=BitAnd(bStatus,MASK_ALL);
    ENDPROC

    PROC build_command(bool start,bool reset,bool lamp)
        bCommand:=0;
        IF start BitSet bCommand,1;
        IF reset BitSet bCommand,2;
        IF lamp THEN
            BitSet bCommand,7;
        ELSE
            BitClear bCommand,7;
        ENDIF
        ! Shift the command into the upper nibble for the second PLC
        bCommand:=BitOr(bCommand,BitLSh(bCommand,4));
        bCommand:=BitXOr(bCommand,0x01);
        ! Same thing on a 52-bit dnum flag word
        dnFlags:=BitOrDnum(dnFlags,NumToDnum(bCommand));
        IF BitCheckDnum(dnFlags,1) TPWrite "Flag word bit 1 set";
    ENDPROC

ENDMODULE
