MODULE string_functions_escapes
    ! String utilities for the label printer and HMI texts.
    ! Covers StrLen, StrPart, StrFind, StrMatch, StrMemb, StrOrder,
    ! StrMap, NumToStr, ValToStr, StrToVal, string escapes and
    ! literals of the maximum length (80 characters).

    ! Exactly 80 characters each
    CONST string MSG_INFEED_BLOCKED:="Station 3 infeed blocked. Remove the part, then press START to resume the cycle.";
    CONST string MSG_GRIPPER_SERVICE:="Check gripper fingers for wear every 5000 cycles and replace both pads together!";
    ! 80 characters after the escapes are resolved
    CONST string MSG_BACKUP_DONE:="Backup ""BACKUP:\\Cell4\\2021_07_14"" written, file size OK, checksum verified: OK.\0A";
    ! Escapes: "" is a quote, \\ a backslash, \hh a character code
    CONST string QUOTE:="""";
    CONST string BACKSLASH:="\\";
    CONST string LF:="\0A";
    CONST string CR_LF:="\0D\0A";
    CONST string TAB_CHAR:="\09";
    CONST string LABEL_PREFIX:="LBL\3A";

    VAR string sLabel:="";
    VAR num nValue:=0;
    VAR pos psValue:=[0,0,0];
    CONST pos PS_SAMPLE:=[12.5,-3,400];
    VAR bool bOk:=FALSE;

    PROC main()
        VAR string sSerial;
        sSerial:=make_serial("ab-1234/x",17);
        TPWrite sSerial;
        TPWrite MSG_INFEED_BLOCKED;
        TPWrite MSG_GRIPPER_SERVICE;
        TPWrite "Length of backup message: "\Num:=StrLen(MSG_BACKUP_DONE);
        sLabel:=QUOTE+"Part "+sSerial+QUOTE+TAB_CHAR+"C:"+BACKSLASH+"labels"+LF;
        parse_values;
        TPWrite "Trimmed: ["+trim("   spaced text   ")+"]";
        TPWrite "Digits only: "+keep_digits("L-45/B 0917");
        IF StrOrder("BRACKET","COVER",STR_UPPER) TPWrite "BRACKET sorts first";
    ENDPROC

    ! Upper-case the code, remove the '-' and append a counter
    FUNC string make_serial(string code,num counter)
        VAR string s;
        VAR num nDash;
        s:=StrMap(code,STR_LOWER,STR_UPPER);
        nDash:=StrFind(s,1,"-");
        IF nDash<=StrLen(s) THEN
            s:=StrPart(s,1,nDash-1)+StrPart(s,nDash+1,StrLen(s)-nDash);
        ENDIF
        ! Cut at the first '/' if any
        IF StrMatch(s,1,"/")<=StrLen(s) s:=StrPart(s,1,StrMatch(s,1,"/")-1);
        RETURN s+"-"+NumToStr(counter,0);
    ENDFUNC

    FUNC string trim(string text)
        VAR num nFirst;
        VAR num nLast;
        nFirst:=StrFind(text,1,STR_WHITE\NotInSet);
        IF nFirst>StrLen(text) RETURN "";
        nLast:=StrLen(text);
        WHILE StrMemb(text,nLast,STR_WHITE) DO
            nLast:=nLast-1;
        ENDWHILE
        RETURN StrPart(text,nFirst,nLast-nFirst+1);
    ENDFUNC

    FUNC string keep_digits(string text)
        VAR string sOut:="";
        FOR i FROM 1 TO StrLen(text) DO
            IF StrMemb(text,i,STR_DIGIT) sOut:=sOut+StrPart(text,i,1);
        ENDFOR
        RETURN sOut;
    ENDFUNC

    PROC parse_values()
        VAR string sText;
        ! Number to text with decimals and in exponent form
        TPWrite NumToStr(3.14159,2);
        TPWrite NumToStr(0.000123,3\Exp);
        ! Any value type to text and back
        sText:=ValToStr(PS_SAMPLE);
        bOk:=StrToVal(sText,psValue);
        IF bOk TPWrite "pos parsed, x = "\Num:=psValue.x;
        bOk:=StrToVal("42.75",nValue);
        IF NOT bOk THEN
            TPWrite "not a number";
        ENDIF
        sText:=ValToStr(bOk)+" "+ValToStr(nValue);
        TPWrite sText;
    ERROR
        IF ERRNO=ERR_STRTOOLNG THEN
            TPWrite "Text too long";
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
