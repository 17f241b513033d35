MODULE MainModule
    PERS num placed := 0;

    PROC cell_main()
        IF diPalletReady = 1 AND giLayerPattern <> 0 THEN
            TPWrite "waiting for a part, pattern " \Num:=giLayerPattern;
            WaitDI diPartAtPick, 1;
            pick_part;
            place_part;
        ELSE
            TPWrite "Pallet not ready, pattern " \Num:=giLayerPattern;
        ENDIF
        SetAO aoConveyorSpeed, 120;
        PulseDO \PLength:=0.5, doCycleDone;
    ENDPROC

    PROC pick_part()
        Set doGripperClose;
        WaitTime 0.2;
        IF diVacuumOk = 0 RAISE ERR_ARGVALERR;
    ENDPROC

    PROC place_part()
        Reset doGripperClose;
        Incr placed;
        SetGO goPlacedCount, placed;
        TPWrite "placed " \Num:=placed;
    ENDPROC
ENDMODULE
