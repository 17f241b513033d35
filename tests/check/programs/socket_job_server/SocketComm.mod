MODULE SocketComm
    ! TCP connection to the cell PC. Jobs arrive as text lines
    ! "JOB;<id>;<station>", answers are "DONE;<id>" or "FAIL;<id>".

    VAR socketdev sockListen;
    VAR socketdev sockPc;
    VAR bool bPcConnected:=FALSE;
    CONST num COMM_PORT:=1030;

    PROC comm_open()
        SocketClose sockListen;
        SocketCreate sockListen;
        SocketBind sockListen,"192.168.125.1",COMM_PORT;
        SocketListen sockListen;
        SocketAccept sockListen,sockPc\Time:=120;
        bPcConnected:=TRUE;
    ERROR
        IF ERRNO=ERR_SOCK_TIMEOUT THEN
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    ! Reads one message; returns FALSE when nothing arrived in time
    FUNC bool comm_receive(VAR string message)
        SocketReceive sockPc\Str:=message\Time:=5;
        RETURN TRUE;
    ERROR
        IF ERRNO=ERR_SOCK_TIMEOUT THEN
            RETURN FALSE;
        ELSEIF ERRNO=ERR_SOCK_CLOSED THEN
            bPcConnected:=FALSE;
            RETURN FALSE;
        ENDIF
        RAISE;
    ENDFUNC

    PROC comm_send(string message)
        SocketSend sockPc\Str:=message+"\0A";
    ERROR
        IF ERRNO=ERR_SOCK_CLOSED THEN
            bPcConnected:=FALSE;
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    PROC comm_close()
        SocketClose sockPc;
        SocketClose sockListen;
        bPcConnected:=FALSE;
    ENDPROC

ENDMODULE
