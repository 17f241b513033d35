MODULE rmq_task_messaging
    ! RAPID Message Queue between the robot task T_ROB1 and the
    ! vision task T_VISION. T_ROB1 asks for a part position and gets
    ! a record back; status texts arrive asynchronously by interrupt.

    RECORD vision_result
        num part_id;
        num x;
        num y;
        num angle;
        bool found;
    ENDRECORD

    VAR rmqslot rsVision;
    VAR rmqslot rsSender;
    VAR rmqmessage rmMsg;
    VAR rmqheader rhHeader;
    VAR vision_result vrResult;
    VAR vision_result vrTemplate;
    VAR string sStatus:="";
    VAR string sRequest:="";
    VAR num nUserDef:=0;
    VAR intnum irStatus;
    VAR num nStatusMsgs:=0;

    PERS tooldata tPicker:=[TRUE,[[0,0,140],[1,0,0,0]],[0.8,[0,0,50],[1,0,0,0],0,0,0]];
    CONST robtarget pCamZero:=[[800,-200,350],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        RMQEmptyQueue;
        RMQFindSlot rsVision,"RMQ_T_VISION";
        IDelete irStatus;
        CONNECT irStatus WITH trap_status;
        ! Interrupt on every incoming message of data type string
        IRMQMessage sStatus,irStatus;
        WHILE TRUE DO
            IF request_part() THEN
                pick_found_part;
            ELSE
                WaitTime 1;
            ENDIF
        ENDWHILE
    ENDPROC

    ! Synchronous request/answer with RMQSendWait
    FUNC bool request_part()
        sRequest:="FIND;GEAR_32T";
        RMQSendWait rsVision,sRequest\UserDef:=7,rmMsg,vrTemplate\Timeout:=5;
        RMQGetMsgHeader rmMsg\Header:=rhHeader\SenderId:=rsSender\UserDef:=nUserDef;
        IF rhHeader.datatype<>"vision_result" RETURN FALSE;
        RMQGetMsgData rmMsg,vrResult;
        RETURN vrResult.found;
    ERROR
        IF ERRNO=ERR_RMQ_TIMEOUT THEN
            TPWrite "Vision task did not answer";
            RETURN FALSE;
        ELSEIF ERRNO=ERR_RMQ_NAME THEN
            TPWrite "Slot name not configured";
            RETURN FALSE;
        ENDIF
        RAISE;
    ENDFUNC

    PROC pick_found_part()
        VAR robtarget pTarget;
        pTarget:=RelTool(Offs(pCamZero,vrResult.x,vrResult.y,0),0,0,0\Rz:=vrResult.angle);
        MoveJ Offs(pTarget,0,0,100),v1000,z20,tPicker;
        MoveL pTarget,v200,fine,tPicker;
        MoveL Offs(pTarget,0,0,100),v1000,z20,tPicker;
        ! Tell the vision task which part was taken (asynchronous)
        RMQSendMessage rsVision,vrResult\UserDef:=1;
    ENDPROC

    ! Polling variant, used when interrupts are disabled
    PROC wait_for_status()
        RMQReadWait rmMsg\TimeOut:=10;
        RMQGetMsgHeader rmMsg\Header:=rhHeader;
        IF rhHeader.datatype="string" AND rhHeader.ndim=0 THEN
            RMQGetMsgData rmMsg,sStatus;
            TPWrite "Vision: "+sStatus;
        ENDIF
    ERROR
        IF ERRNO=ERR_RMQ_TIMEOUT THEN
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    TRAP trap_status
        RMQGetMessage rmMsg;
        RMQGetMsgHeader rmMsg\SenderId:=rsSender;
        RMQGetMsgData rmMsg,sStatus;
        nStatusMsgs:=nStatusMsgs+1;
        TPWrite RMQGetSlotName(rsSender)+": "+sStatus;
    ENDTRAP

ENDMODULE
