MODULE ui_result_pers
    ! ABB's syntax gives UIMsgBox \Result, UIListView \Result and the TPAnswer of
    ! TPReadNum / TPReadDnum / TPReadFK as "var or pers (INOUT)": a PERS may take the
    ! answer (a RobotWare 6.13 backup passes a TASK PERS to UIListView \Result).
    ! Without an operator and with \BreakFlag, \Result gets resUnkwn (0), UIListView
    ! returns 0 and TPReadNum / TPReadFK leave TPAnswer as it was.
    TASK PERS btnres rAnswer := 5;
    PERS num nAnswer := 9;
    CONST listitem liMenu{2} := [["", "Pick"], ["", "Place"]];

    PROC main()
        VAR errnum flag;
        UIMsgBox "Go on?" \Buttons:=btnOKCancel \Result:=rAnswer \BreakFlag:=flag;
        IF flag = ERR_TP_NO_CLIENT TPWrite "no client";
        TPWrite "box " \Num:=rAnswer;
        rAnswer := 5;
        nAnswer := UIListView(\Result:=rAnswer \Header:="Menu", liMenu \Buttons:=btnOKCancel \BreakFlag:=flag);
        TPWrite "list " \Num:=rAnswer;
        TPWrite "item " \Num:=nAnswer;
        nAnswer := 9;
        TPReadNum nAnswer, "How many?" \BreakFlag:=flag;
        TPReadFK nAnswer, "Go on?", "Yes", "No", stEmpty, stEmpty, stEmpty \MaxTime:=1 \BreakFlag:=flag;
        IF flag = ERR_TP_MAXTIME TPWrite "timeout";
        TPWrite "answer " \Num:=nAnswer;
    ENDPROC
ENDMODULE
