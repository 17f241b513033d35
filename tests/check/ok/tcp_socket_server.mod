MODULE tcp_socket_server
    !-----------------------------------------------------------------
    ! Simple line based command server for a cell PC.
    ! Protocol (ASCII, one command per message, answer "ACK;..." or
    ! "NAK;reason"):
    !   PING                -> ACK;PONG
    !   GOTO;<n>            -> move to station n (1..4)
    !   SPEED;<percent>     -> VelSet override
    !   STATUS              -> ACK;<cycles>;<speed>
    !   BYE                 -> closes the client connection
    !-----------------------------------------------------------------

    VAR socketdev sockServer;
    VAR socketdev sockClient;
    VAR string sClientIp:="";
    VAR string sRx:="";
    VAR string sTx:="";
    VAR bool bConnected:=FALSE;
    VAR bool bRunServer:=TRUE;
    VAR num nTimeouts:=0;
    VAR num nCycles:=0;
    VAR num nSpeed:=100;

    CONST string SERVER_IP:="192.168.125.1";
    CONST num SERVER_PORT:=1025;
    CONST num RX_TIMEOUT:=30;
    CONST num MAX_TIMEOUTS:=10;

    PERS tooldata tPointer:=[TRUE,[[0,0,100],[1,0,0,0]],[0.5,[0,0,40],[1,0,0,0],0,0,0]];
    CONST robtarget pStation{4}:=[[[500,-300,400],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[500,-100,400],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[500,100,400],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[500,300,400],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]]];

    PROC main()
        open_server;
        WHILE bRunServer DO
            wait_for_client;
            serve_client;
        ENDWHILE
        SocketClose sockServer;
    ENDPROC

    PROC open_server()
        SocketClose sockServer;
        SocketCreate sockServer;
        SocketBind sockServer,SERVER_IP,SERVER_PORT;
        SocketListen sockServer;
        TPWrite "Server listening on port "\Num:=SERVER_PORT;
    ENDPROC

    PROC wait_for_client()
        SocketAccept sockServer,sockClient\ClientAddress:=sClientIp\Time:=60;
        bConnected:=TRUE;
        nTimeouts:=0;
        TPWrite "Client connected: "+sClientIp;
    ERROR
        IF ERRNO=ERR_SOCK_TIMEOUT THEN
            ! Nobody connected within 60 s - keep waiting
            RETRY;
        ELSEIF ERRNO=ERR_SOCK_CLOSED THEN
            open_server;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC serve_client()
        WHILE bConnected DO
            SocketReceive sockClient\Str:=sRx\Time:=RX_TIMEOUT;
            handle_command sRx;
            IF bConnected THEN
                SocketSend sockClient\Str:=sTx;
            ENDIF
        ENDWHILE
        SocketClose sockClient;
    ERROR
        TEST ERRNO
        CASE ERR_SOCK_TIMEOUT:
            Incr nTimeouts;
            IF nTimeouts<MAX_TIMEOUTS THEN
                ! Client is idle, just read again
                RETRY;
            ENDIF
            TPWrite "Client idle too long, dropping it";
            bConnected:=FALSE;
            TRYNEXT;
        CASE ERR_SOCK_CLOSED:
            TPWrite "Client closed the connection";
            bConnected:=FALSE;
            ! Skip the failing receive/send and leave the loop
            TRYNEXT;
        DEFAULT:
            RAISE;
        ENDTEST
    ENDPROC

    PROC handle_command(string cmd)
        VAR num nSep;
        VAR string sKey;
        VAR string sArg;
        VAR num nArg;

        nSep:=StrFind(cmd,1,";");
        sKey:=StrPart(cmd,1,nSep-1);
        IF nSep<StrLen(cmd) THEN
            sArg:=StrPart(cmd,nSep+1,StrLen(cmd)-nSep);
        ELSE
            sArg:="";
        ENDIF

        TEST sKey
        CASE "PING":
            sTx:="ACK;PONG";
        CASE "GOTO":
            IF StrToVal(sArg,nArg) AND nArg>=1 AND nArg<=4 THEN
                MoveJ pStation{nArg},v500,fine,tPointer;
                Incr nCycles;
                sTx:="ACK;GOTO;"+NumToStr(nArg,0);
            ELSE
                sTx:="NAK;bad station";
            ENDIF
        CASE "SPEED":
            IF StrToVal(sArg,nArg) THEN
                IF nArg>0 AND nArg<=100 THEN
                    nSpeed:=nArg;
                    VelSet nSpeed,1000;
                    sTx:="ACK;SPEED;"+NumToStr(nSpeed,0);
                ELSE
                    sTx:="NAK;speed out of range";
                ENDIF
            ELSE
                sTx:="NAK;speed not numeric";
            ENDIF
        CASE "STATUS":
            sTx:="ACK;"+NumToStr(nCycles,0)+";"+NumToStr(nSpeed,0);
        CASE "BYE","QUIT":
            sTx:="ACK;BYE";
            SocketSend sockClient\Str:=sTx;
            bConnected:=FALSE;
        DEFAULT:
            sTx:="NAK;unknown command "+sKey;
        ENDTEST
    ENDPROC

ENDMODULE
