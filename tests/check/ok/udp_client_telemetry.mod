MODULE udp_client_telemetry
    ! Sends the current TCP position and a status word to a monitoring
    ! PC every cycle as a UDP datagram, and polls for a one-byte command
    ! reply. Binary layout (big-endian):
    !   byte 1      : 0xA5 header
    !   bytes 2-3   : sequence number (UINT)
    !   bytes 4-15  : x, y, z (Float4)
    !   bytes 16-19 : status word (UDINT)

    VAR socketdev sockUdp;
    VAR rawbytes rawTx;
    VAR rawbytes rawRx;
    VAR string sPeerIp:="";
    VAR num nPeerPort:=0;
    VAR num nSeq:=0;
    VAR num nStatusWord:=0;
    VAR byte bHeader:=0xA5;
    VAR byte bReply:=0;
    VAR robtarget pNow;

    CONST string MONITOR_IP:="192.168.125.50";
    CONST num MONITOR_PORT:=6510;
    CONST num LOCAL_PORT:=6511;

    PROC main()
        udp_open;
        FOR i FROM 1 TO 1000 DO
            send_telemetry;
            poll_reply;
            WaitTime 0.1;
        ENDFOR
        SocketClose sockUdp;
    ENDPROC

    PROC udp_open()
        SocketCreate sockUdp\UDP;
        SocketBind sockUdp,"192.168.125.1",LOCAL_PORT;
    ENDPROC

    PROC send_telemetry()
        pNow:=CRobT(\Tool:=tool0\WObj:=wobj0);
        nSeq:=(nSeq+1) MOD 65536;
        ClearRawBytes rawTx;
        PackRawBytes bHeader,rawTx,1\Hex1;
        PackRawBytes nSeq,rawTx\Network,2\IntX:=UINT;
        PackRawBytes pNow.trans.x,rawTx\Network,4\Float4;
        PackRawBytes pNow.trans.y,rawTx\Network,8\Float4;
        PackRawBytes pNow.trans.z,rawTx\Network,12\Float4;
        PackRawBytes nStatusWord,rawTx\Network,RawBytesLen(rawTx)+1\IntX:=UDINT;
        SocketSendTo sockUdp,MONITOR_IP,MONITOR_PORT\RawData:=rawTx;
    ENDPROC

    PROC poll_reply()
        VAR num nBytes;
        ClearRawBytes rawRx;
        SocketReceiveFrom sockUdp\RawData:=rawRx\NoRecBytes:=nBytes,sPeerIp,nPeerPort\Time:=0.05;
        IF nBytes>=1 THEN
            UnpackRawBytes rawRx,1,bReply\Hex1;
            TEST bReply
            CASE 1:
                nStatusWord:=BitOr(nStatusWord,1);
            CASE 2:
                nStatusWord:=0;
            DEFAULT:
                TPWrite "Unknown reply byte "\Num:=bReply;
            ENDTEST
        ENDIF
    ERROR
        IF ERRNO=ERR_SOCK_TIMEOUT THEN
            ! No reply this cycle, that is normal
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

ENDMODULE
