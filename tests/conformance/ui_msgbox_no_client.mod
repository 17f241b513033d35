MODULE ui_msgbox_no_client
    ! No answers are given (rapid run without --tp-input): every dialog fails as with
    ! no FlexPendant connected, ERR_TP_NO_CLIENT, which the ERROR handler takes.
    ! UIMsgBox without \Buttons shows one OK button (ABB default), but nobody presses it.
    VAR num nHandled := 0;

    PROC AskOperator()
        VAR btnres answer := resYes;
        UIMsgBox \Header:="Check", "Gripper closed?" \MsgLine2:="Press Yes or No" \Buttons:=btnYesNo \Icon:=iconQuestion \Result:=answer;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_TP_NO_CLIENT THEN
            nHandled := nHandled + 1;
            TPWrite "no pendant for UIMsgBox";
            RETURN;
        ENDIF
    ENDPROC

    PROC main()
        AskOperator;
        UIMsgBox "Plain message";
        TPWrite "not reached either";
    ERROR
        IF ERRNO = ERR_TP_NO_CLIENT THEN
            nHandled := nHandled + 1;
            TPWrite "handled in main";
            TPWrite "handled: " \Num:=nHandled;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
