MODULE recipe_csv_loader
    ! Loads glue dispensing recipes from HOME:/recipes/glue.csv
    ! File layout, first line is a header that is skipped:
    !   name,flow,speed,offset_z,passes
    !   DOOR_LH,62.5,180,1.2,2
    ! Recipes are kept in parallel arrays (max. 10 recipes).

    CONST num MAX_RECIPES:=10;
    CONST string RECIPE_PATH:="HOME:/recipes/glue.csv";
    CONST string BACKUP_PATH:="HOME:/recipes/glue_backup.csv";

    VAR string sRecipeName{10};
    VAR num nFlow{10};
    VAR num nSpeed{10};
    VAR num nOffsetZ{10};
    VAR num nPasses{10};
    VAR num nRecipes:=0;
    VAR iodev ioCsv;

    PROC main()
        VAR num nIdx;
        IF NOT IsFile(RECIPE_PATH\RegFile) THEN
            TPWrite "Recipe file missing, using backup";
            CopyFile BACKUP_PATH,RECIPE_PATH;
        ENDIF
        TPWrite "Recipe file size: "\Num:=FileSize(RECIPE_PATH);
        load_recipes;
        nIdx:=find_recipe("DOOR_LH");
        IF nIdx>0 THEN
            TPWrite "DOOR_LH flow="\Num:=nFlow{nIdx};
        ENDIF
    ENDPROC

    PROC load_recipes()
        VAR string sField;
        VAR string sHeader;
        VAR num nValue;
        VAR bool bOk;
        VAR num nCol;

        nRecipes:=0;
        Open RECIPE_PATH,ioCsv\Read;
        ! Skip the header line
        sHeader:=ReadStr(ioCsv\RemoveCR);
        ! Read field by field; "," and line feed both end a field
        sField:=ReadStr(ioCsv\Delim:=","\RemoveCR\DiscardHeaders);
        WHILE sField<>EOF AND nRecipes<MAX_RECIPES DO
            nRecipes:=nRecipes+1;
            sRecipeName{nRecipes}:=sField;
            FOR col FROM 2 TO 5 DO
                sField:=ReadStr(ioCsv\Delim:=","\RemoveCR\DiscardHeaders);
                bOk:=StrToVal(sField,nValue);
                IF NOT bOk THEN
                    TPWrite "Bad value in recipe "+sRecipeName{nRecipes}+": "+sField;
                    nValue:=0;
                ENDIF
                nCol:=col;
                store_field nRecipes,nCol,nValue;
            ENDFOR
            sField:=ReadStr(ioCsv\Delim:=","\RemoveCR\DiscardHeaders);
        ENDWHILE
        Close ioCsv;
        TPWrite "Recipes loaded: "\Num:=nRecipes;
    ERROR
        IF ERRNO=ERR_FILEOPEN THEN
            TPWrite "Cannot open "+RECIPE_PATH;
            nRecipes:=0;
            RETURN;
        ENDIF
        Close ioCsv;
        RAISE;
    ENDPROC

    PROC store_field(num idx,num col,num value)
        TEST col
        CASE 2:
            nFlow{idx}:=value;
        CASE 3:
            nSpeed{idx}:=value;
        CASE 4:
            nOffsetZ{idx}:=value;
        CASE 5:
            nPasses{idx}:=Round(value);
        ENDTEST
    ENDPROC

    FUNC num find_recipe(string name)
        FOR i FROM 1 TO nRecipes DO
            IF sRecipeName{i}=name RETURN i;
        ENDFOR
        RETURN 0;
    ENDFUNC

ENDMODULE
