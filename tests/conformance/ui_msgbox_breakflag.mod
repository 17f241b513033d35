MODULE ui_msgbox_breakflag
    ! With \BreakFlag the dialog's error is stored there instead of being raised:
    ! ERR_TP_MAXTIME when \MaxTime was given, ERR_TP_NO_CLIENT otherwise, and
    ! \Result gets resUnkwn (no button was pressed).
    ! btnNone shows no buttons at all: the box only ends by \MaxTime (or a break signal).
    PROC main()
        VAR btnres answer := resOK;
        VAR errnum flag;

        UIMsgBox \Header:="Wait", "Robot moves" \Buttons:=btnOKCancel \Result:=answer \MaxTime:=10 \BreakFlag:=flag;
        IF flag = ERR_TP_MAXTIME TPWrite "timed out";
        IF answer = resUnkwn TPWrite "no button";

        answer := resCancel;
        UIMsgBox "Continue?" \Buttons:=btnYesNo \Result:=answer \BreakFlag:=flag;
        IF flag = ERR_TP_NO_CLIENT TPWrite "no client";
        IF answer = resUnkwn TPWrite "no button again";

        UIMsgBox "Please wait" \Buttons:=btnNone \MaxTime:=2 \BreakFlag:=flag;
        IF flag = ERR_TP_MAXTIME TPWrite "btnNone timed out";
        TPWrite "done";
    ENDPROC
ENDMODULE
