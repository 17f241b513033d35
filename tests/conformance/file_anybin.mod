MODULE file_anybin
    ! WriteAnyBin writes a value of any value type; ReadAnyBin reads it back into data
    ! of the same type, identically (manual). At end of file ReadAnyBin raises
    ! ERR_RANYBIN_EOF.
    RECORD item
        string name;
        num count;
        bool ok;
        pos where;
    ENDRECORD

    PROC main()
        VAR iodev f;
        VAR item it := ["bolt", 12, TRUE, [1,2,3]];
        VAR num grid{2,3} := [[1,2,3],[4,5,6]];
        VAR dnum big := 4294967296;
        VAR string text := "quote""d";
        VAR item it2;
        VAR num grid2{2,3};
        VAR dnum big2;
        VAR string text2;
        VAR num n := 1;
        Open "HOME:/values.bin", f \Write \Bin;
        WriteAnyBin f, it;
        WriteAnyBin f, grid;
        WriteAnyBin f, big;
        WriteAnyBin f, text;
        WriteAnyBin f, 0.125;
        Close f;
        Open "HOME:/values.bin", f \Read \Bin;
        ReadAnyBin f, it2;
        ReadAnyBin f, grid2;
        ReadAnyBin f, big2;
        ReadAnyBin f, text2;
        ReadAnyBin f, n;
        TPWrite it2.name + " " + NumToStr(it2.count, 0) \Pos:=it2.where;
        TPWrite "same item=" \Bool:=(it2 = it);
        TPWrite "same grid=" \Bool:=(grid2 = grid);
        TPWrite "grid{2,3}=" \Num:=grid2{2,3};
        TPWrite "big=" \Bool:=(big2 = big);
        TPWrite text2;
        TPWrite "n=" \Num:=n;
        ReadAnyBin f, n;
        TPWrite "not reached";
        Close f;
    ERROR
        IF ERRNO = ERR_RANYBIN_EOF THEN
            TPWrite "end: ERR_RANYBIN_EOF, n=" \Num:=n;
            Close f;
            RETURN;
        ENDIF
    ENDPROC
ENDMODULE
