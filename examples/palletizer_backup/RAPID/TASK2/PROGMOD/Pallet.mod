MODULE Pallet
    ! Layer patterns the PLC selects with giLayerPattern.
    CONST num layer_count := 6;

    FUNC num pattern_rows(num pattern)
        TEST pattern
        CASE 1:
            RETURN 3;
        CASE 2:
            RETURN 4;
        DEFAULT:
            RETURN 2;
        ENDTEST
    ENDFUNC
ENDMODULE
