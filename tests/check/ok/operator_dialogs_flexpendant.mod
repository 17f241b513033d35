MODULE operator_dialogs_flexpendant
    ! Operator dialogs at program start: batch size, product choice
    ! and confirmations. TPReadFK / TPReadNum with time-outs and
    ! break flags, UIMsgBox instruction and UIMessageBox function.

    VAR num nKey:=0;
    VAR num nBatch:=0;
    VAR btnres brAnswer;
    VAR errnum enBreak;
    VAR string sProduct:="";
    PERS bool bOperatorAbort:=FALSE;

    VAR signaldi di_remote_start;

    PROC main()
        AliasIO "DI_RemoteStart",di_remote_start;
        TPErase;
        TPWrite "Cell 7 - bracket welding";
        TPWrite "Program version "\Num:=2.3;
        choose_product;
        ask_batch_size;
        IF confirm_start() THEN
            TPWrite "Starting batch of "\Num:=nBatch;
        ELSE
            TPWrite "Start cancelled";
            EXIT;
        ENDIF
    ENDPROC

    PROC choose_product()
        TPReadFK nKey,"Select product to run","Bracket","Hinge","Cover",stEmpty,"Cancel"\MaxTime:=60\DIBreak:=di_remote_start\BreakFlag:=enBreak;
        IF enBreak=ERR_TP_MAXTIME THEN
            TPWrite "No selection, using last product";
            RETURN;
        ELSEIF enBreak=ERR_TP_DIBREAK THEN
            TPWrite "Remote start pressed";
            RETURN;
        ENDIF
        TEST nKey
        CASE 1:
            sProduct:="BRACKET";
        CASE 2:
            sProduct:="HINGE";
        CASE 3:
            sProduct:="COVER";
        CASE 5:
            bOperatorAbort:=TRUE;
        ENDTEST
    ENDPROC

    PROC ask_batch_size()
        TPReadNum nBatch,"How many parts in this batch?"\MaxTime:=120;
        WHILE nBatch<1 OR nBatch>500 OR nBatch<>Round(nBatch) DO
            TPWrite "Enter a whole number 1..500";
            TPReadNum nBatch,"How many parts in this batch?";
        ENDWHILE
    ERROR
        IF ERRNO=ERR_TP_MAXTIME THEN
            nBatch:=50;
            TPWrite "Timeout - default batch 50";
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    FUNC bool confirm_start()
        UIMsgBox\Header:="Batch start","Product: "+sProduct\MsgLine2:="Parts: "+NumToStr(nBatch,0)\MsgLine3:="Start the batch now?"\Buttons:=btnYesNo\Icon:=iconQuestion\Result:=brAnswer;
        IF brAnswer<>resYes RETURN FALSE;
        brAnswer:=UIMessageBox(\Header:="Safety"\Message:="Is the cell empty and the door closed?"\Buttons:=btnOKCancel\DefaultBtn:=resCancel\Icon:=iconWarning\MaxTime:=30);
        RETURN brAnswer=resOK;
    ENDFUNC

    PROC show_fault(string text)
        UIMsgBox\Header:="Fault",text\Wrap\Buttons:=btnAbrtRtryIgn\Icon:=iconError\Result:=brAnswer;
        TEST brAnswer
        CASE resAbort:
            EXIT;
        CASE resRetry:
            TPWrite "Retry selected";
        CASE resIgnore:
            TPWrite "Fault ignored";
        DEFAULT:
            TPWrite "Unknown answer";
        ENDTEST
    ENDPROC

ENDMODULE
