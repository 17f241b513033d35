MODULE ui_messagebox_default_btn
    ! UIMessageBox with \BreakFlag and no answer returns \DefaultBtn (resUnkwn when
    ! \DefaultBtn is absent). With \BtnArray the results are array indexes, so
    ! \DefaultBtn is an index too.
    CONST string stButtons{3} := ["Start", "Service", "Exit"];

    FUNC btnres Ask(string text, num maxTime)
        VAR errnum flag;
        VAR btnres answer;
        answer := UIMessageBox(\Header:="Question" \Message:=text \Buttons:=btnOKCancel \DefaultBtn:=resCancel \MaxTime:=maxTime \BreakFlag:=flag);
        IF flag = ERR_TP_MAXTIME TPWrite "timeout";
        RETURN answer;
    ENDFUNC

    PROC main()
        VAR btnres answer;
        VAR errnum flag;

        IF Ask("Start cycle?", 5) = resCancel TPWrite "default is Cancel";

        answer := UIMessageBox(\MsgArray:=["Choose", "the next step"] \BtnArray:=stButtons \DefaultBtn:=3 \BreakFlag:=flag);
        IF flag = ERR_TP_NO_CLIENT TPWrite "no client";
        TEST answer
        CASE 1:
            TPWrite "start";
        CASE 2:
            TPWrite "service";
        CASE 3:
            TPWrite "exit";
        DEFAULT:
            TPWrite "other";
        ENDTEST

        answer := UIMessageBox(\Message:="Go on?" \Buttons:=btnYesNo \BreakFlag:=flag);
        IF answer = resUnkwn TPWrite "unknown without DefaultBtn";
    ENDPROC
ENDMODULE
