MODULE rawbytes_pack_unpack
    ! Binary telegrams for a laser distance sensor on a TCP socket.
    ! Request:  STX(0x02) | cmd (ASCII, 4 chars) | id (UINT) | ETX(0x03)
    ! Response: STX | status (USINT) | distance (Float4) | counter (DINT)
    !           | text (ASCII, 8 chars) | ETX
    ! Multi-byte values are big-endian (\Network).

    VAR socketdev sockSensor;
    VAR rawbytes rbRequest;
    VAR rawbytes rbResponse;
    VAR rawbytes rbCopy;
    VAR byte bStx:=0x02;
    VAR byte bEtx:=0x03;
    VAR byte bFirst;
    VAR byte bLast;
    VAR num nStatus;
    VAR num nDistance;
    VAR num nCounter;
    VAR dnum dnTimestamp;
    VAR string sText;
    VAR num nRequestId:=0;

    PROC main()
        SocketCreate sockSensor;
        SocketConnect sockSensor,"192.168.125.30",2112\Time:=5;
        FOR i FROM 1 TO 5 DO
            request_distance "DIST";
            TPWrite "Distance [mm]: "\Num:=nDistance;
        ENDFOR
        SocketClose sockSensor;
    ERROR
        IF ERRNO=ERR_SOCK_TIMEOUT THEN
            TPWrite "Sensor does not answer";
            SocketClose sockSensor;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    PROC request_distance(string cmd)
        nRequestId:=nRequestId+1;
        ClearRawBytes rbRequest;
        PackRawBytes bStx,rbRequest,1\Hex1;
        PackRawBytes cmd,rbRequest,2\ASCII;
        PackRawBytes nRequestId,rbRequest\Network,RawBytesLen(rbRequest)+1\IntX:=UINT;
        PackRawBytes bEtx,rbRequest,RawBytesLen(rbRequest)+1\Hex1;
        SocketSend sockSensor\RawData:=rbRequest\NoOfBytes:=RawBytesLen(rbRequest);
        ClearRawBytes rbResponse;
        SocketReceive sockSensor\RawData:=rbResponse\ReadNoOfBytes:=20\Time:=2;
        decode_response;
    ENDPROC

    PROC decode_response()
        UnpackRawBytes rbResponse,1,bFirst\Hex1;
        UnpackRawBytes rbResponse,RawBytesLen(rbResponse),bLast\Hex1;
        IF bFirst<>bStx OR bLast<>bEtx THEN
            TPWrite "Framing error";
            RETURN;
        ENDIF
        UnpackRawBytes rbResponse,2,nStatus\IntX:=USINT;
        UnpackRawBytes rbResponse\Network,3,nDistance\Float4;
        UnpackRawBytes rbResponse\Network,7,nCounter\IntX:=DINT;
        UnpackRawBytes rbResponse,11,sText\ASCII:=8;
        ! Keep a copy of the payload without STX/ETX for logging
        ClearRawBytes rbCopy;
        CopyRawBytes rbResponse,2,rbCopy,1\NoOfBytes:=RawBytesLen(rbResponse)-2;
        IF nStatus<>0 TPWrite "Sensor status "+sText\Num:=nStatus;
    ENDPROC

    ! 8 byte timestamps need a dnum
    PROC pack_timestamp(VAR rawbytes target,num index)
        dnTimestamp:=NumToDnum(GetTime(\Hour)*3600+GetTime(\Min)*60+GetTime(\Sec));
        PackRawBytes dnTimestamp,target\Network,index\IntX:=LINT;
        UnpackRawBytes target\Network,index,dnTimestamp\IntX:=LINT;
    ENDPROC

ENDMODULE
