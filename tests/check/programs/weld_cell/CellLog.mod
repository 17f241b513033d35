MODULE CellLog
    ! Event log for the weld cell, written to HOME:/weldcell.log

    LOCAL VAR iodev ioLog;
    LOCAL CONST string LOG_NAME:="weldcell.log";

    PROC log_event(string text)
        Open "HOME:"\File:=LOG_NAME,ioLog\Append;
        Write ioLog,CDate()+" "+CTime()+" "+text;
        Close ioLog;
    ERROR
        IF ERRNO=ERR_FILEOPEN THEN
            TPWrite "LOG: "+text;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
