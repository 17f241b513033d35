MODULE event_log_error_trap
    ! Listens for event log messages and mirrors them to the cell PLC
    ! and to a text file. Uses IError, GetTrapData and ReadErrData.

    VAR intnum irAnyError;
    VAR intnum irMotionWarn;
    VAR intnum irIoError;
    VAR trapdata tdEvent;
    VAR errdomain edDomain;
    VAR num nErrId;
    VAR errtype etType;
    VAR string sTitle;
    VAR string sArg1;
    VAR string sArg2;
    VAR num nEvents:=0;
    VAR iodev ioEvents;

    VAR signalgo go_error_code;
    VAR signaldo do_error_active;

    PROC main()
        AliasIO "goErrorCode",go_error_code;
        AliasIO "doErrorActive",do_error_active;
        IDelete irAnyError;
        IDelete irMotionWarn;
        IDelete irIoError;
        CONNECT irAnyError WITH trap_event;
        CONNECT irMotionWarn WITH trap_event;
        CONNECT irIoError WITH trap_event;
        ! Any error in any domain
        IError COMMON_ERR,TYPE_ERR,irAnyError;
        ! Motion warnings only
        IError MOTION_ERR,TYPE_WARN,irMotionWarn;
        ! One specific I/O event: 71058 "Lost communication with I/O device"
        IError IO_COM_ERR\ErrorId:=58,TYPE_ALL,irIoError;
        WHILE TRUE DO
            WaitTime 10;
            IF nEvents>0 TPWrite "Events mirrored: "\Num:=nEvents;
        ENDWHILE
    ENDPROC

    TRAP trap_event
        GetTrapData tdEvent;
        ReadErrData tdEvent,edDomain,nErrId,etType\Title:=sTitle\Str1:=sArg1\Str2:=sArg2;
        nEvents:=nEvents+1;
        SetGO go_error_code,edDomain*1000+nErrId MOD 1000;
        IF etType=TYPE_ERR THEN
            Set do_error_active;
        ENDIF
        write_event;
    ENDTRAP

    PROC write_event()
        Open "HOME:"\File:="events.log",ioEvents\Append;
        Write ioEvents,CDate()+" "+CTime()+" domain "\Num:=edDomain\NoNewLine;
        Write ioEvents," id "\Num:=nErrId\NoNewLine;
        Write ioEvents," "+sTitle;
        Close ioEvents;
    ERROR
        ! Never let the logger stop the trap
        SkipWarn;
        TRYNEXT;
    ENDPROC

ENDMODULE
