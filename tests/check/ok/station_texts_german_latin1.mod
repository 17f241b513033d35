MODULE station_texts_german_latin1
    ! Bedientexte für Station 5 (Fügen der Lagerschale).
    ! Datei im ISO-8859-1 Zeichensatz gespeichert: ä ö ü Ä Ö Ü ß °
    ! Änderung 2020-11-03: Texte für Größe XL ergänzt (Jürgen Weiß)

    CONST string TXT_TITLE:="Fügestation 5 - Lagerschale";
    CONST string TXT_DOOR:="Schutztür schließen und Quittieren drücken";
    CONST string TXT_PRESS:="Einpresskraft zu groß - Teil prüfen!";
    CONST string TXT_TEMP:="Öltemperatur über 60 °C";
    CONST string TXT_SIZES{3}:=["Größe S","Größe M","Größe XL"];
    CONST string TXT_DONE:="Zyklus beendet, Stückzahl: ";

    VAR num nForce:=0;
    VAR num nSize:=1;
    VAR num nCount:=0;
    VAR signaldi di_door;
    VAR signalai ai_force;
    VAR signalai ai_oil_temp;
    VAR signaldo do_press_down;

    PROC main()
        AliasIO "DI_Schutztuer",di_door;
        AliasIO "AI_Einpresskraft",ai_force;
        AliasIO "AI_Oeltemperatur",ai_oil_temp;
        AliasIO "DO_PresseAb",do_press_down;
        TPErase;
        TPWrite TXT_TITLE;
        ! Prüfen, ob die Tür geschlossen ist
        IF di_door=0 THEN
            TPWrite TXT_DOOR;
            WaitDI di_door,1;
        ENDIF
        FOR i FROM 1 TO 3 DO
            nSize:=i;
            fuegen;
        ENDFOR
        TPWrite TXT_DONE\Num:=nCount;
    ENDPROC

    ! Fügen: Presse ab, Kraft überwachen, Presse auf
    PROC fuegen()
        TPWrite "Fügen "+TXT_SIZES{nSize};
        IF AInput(ai_oil_temp)>60 TPWrite TXT_TEMP;
        SetDO do_press_down,1;
        WaitTime 1.2;
        nForce:=AInput(ai_force);
        SetDO do_press_down,0;
        IF nForce>18.5 THEN
            ! Kraft zu hoch -> Meldung, Teil wird ausgeschleust
            ErrWrite\W,"Fügekraft","Einpresskraft überschritten"\RL2:="Kraft [kN]: "+NumToStr(nForce,1);
            TPWrite TXT_PRESS;
        ELSE
            nCount:=nCount+1;
        ENDIF
    ENDPROC

ENDMODULE
