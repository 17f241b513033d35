MODULE file_logger
    !----------------------------------------------------------------
    ! Production logger. Appends one line per cycle to HOME:/prodlog.txt
    ! and can read the log back to compute statistics. A second file,
    ! cycletimes.txt, holds one number per line and is read with ReadNum.
    !----------------------------------------------------------------

    VAR iodev ioLog;
    VAR iodev ioTimes;
    VAR clock clkCycle;
    VAR num nLogErrors:=0;
    VAR bool bLogOpen:=FALSE;
    PERS num nLogLines:=0;

    CONST string LOG_DIR:="HOME:";
    CONST string LOG_FILE:="prodlog.txt";
    CONST string TIMES_FILE:="cycletimes.txt";

    PROC main()
        VAR num nCycle;
        FOR nRun FROM 1 TO 5 DO
            ClkReset clkCycle;
            ClkStart clkCycle;
            WaitTime 0.5;
            ClkStop clkCycle;
            nCycle:=ClkRead(clkCycle);
            log_cycle nRun,nCycle;
        ENDFOR
        report_statistics;
        TPWrite "Average cycle: "\Num:=average_cycle_time();
    ENDPROC

    ! Append one record to the production log
    PROC log_cycle(num part_no,num cycle_time)
        Open LOG_DIR\File:=LOG_FILE,ioLog\Append;
        bLogOpen:=TRUE;
        Write ioLog,CDate()+" "+CTime()+";"\NoNewLine;
        Write ioLog,"part="\Num:=part_no\NoNewLine;
        Write ioLog,";t="\Num:=cycle_time\NoNewLine;
        Write ioLog,";ok="\Bool:=cycle_time<30;
        Close ioLog;
        bLogOpen:=FALSE;
        nLogLines:=nLogLines+1;
        ! Separate file with only the numbers, for ReadNum
        Open LOG_DIR\File:=TIMES_FILE,ioTimes\Append;
        Write ioTimes,""\Num:=cycle_time;
        Close ioTimes;
    ERROR
        IF ERRNO=ERR_FILEOPEN THEN
            Incr nLogErrors;
            TPWrite "Log file could not be opened, errors: "\Num:=nLogErrors;
            ! Skip logging for this cycle
            RETURN;
        ENDIF
        RAISE;
    UNDO
        IF bLogOpen Close ioLog;
    ENDPROC

    ! Read the log line by line until EOF and count good/bad parts
    PROC report_statistics()
        VAR string sLine;
        VAR num nGood:=0;
        VAR num nBad:=0;
        VAR num nLines:=0;

        Open LOG_DIR\File:=LOG_FILE,ioLog\Read;
        sLine:=ReadStr(ioLog\RemoveCR);
        WHILE sLine<>EOF DO
            Incr nLines;
            IF StrMatch(sLine,1,"ok=TRUE")<=StrLen(sLine) THEN
                Incr nGood;
            ELSE
                Incr nBad;
            ENDIF
            sLine:=ReadStr(ioLog\RemoveCR);
        ENDWHILE
        Close ioLog;
        TPWrite "Lines read: "\Num:=nLines;
        TPWrite "Good parts: "\Num:=nGood;
        TPWrite "Bad parts:  "\Num:=nBad;
    ERROR
        IF ERRNO=ERR_FILEOPEN THEN
            TPWrite "No production log yet";
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! Sum all numbers in the times file until ReadNum hits EOF
    FUNC num average_cycle_time()
        VAR num nValue;
        VAR num nSum:=0;
        VAR num nCount:=0;

        Open LOG_DIR\File:=TIMES_FILE,ioTimes\Read;
        nValue:=ReadNum(ioTimes);
        WHILE nValue<>EOF_NUM DO
            nSum:=nSum+nValue;
            nCount:=nCount+1;
            nValue:=ReadNum(ioTimes\Time:=2);
        ENDWHILE
        Close ioTimes;
        IF nCount=0 RETURN 0;
        RETURN nSum/nCount;
    ERROR
        IF ERRNO=ERR_FILEOPEN THEN
            RETURN 0;
        ELSEIF ERRNO=ERR_RCVDATA THEN
            ! A corrupt line: skip it and go on reading
            TRYNEXT;
        ENDIF
        RETURN -1;
    ENDFUNC

ENDMODULE
