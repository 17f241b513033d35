MODULE ui_listview_no_client
    ! UIListView without an answer: ERR_TP_NO_CLIENT (ERR_TP_MAXTIME with \MaxTime)
    ! goes to the ERROR handler, which here answers for the operator with RETURN.
    ! With \BreakFlag the function returns 0 (no item) and \Result gets resUnkwn.
    CONST listitem liMenu{3} := [["", "Pick"], ["", "Place"], ["", "Home"]];

    FUNC num ChooseItem(num maxTime)
        VAR btnres button;
        IF maxTime > 0 THEN
            RETURN UIListView(\Result:=button \Header:="Menu", liMenu \Buttons:=btnOKCancel \DefaultIndex:=1 \MaxTime:=maxTime);
        ENDIF
        RETURN UIListView(\Header:="Menu", liMenu);
    ERROR
        IF ERRNO = ERR_TP_NO_CLIENT THEN
            TPWrite "no client: default 3";
            RETURN 3;
        ELSEIF ERRNO = ERR_TP_MAXTIME THEN
            TPWrite "timeout: default 1";
            RETURN 1;
        ENDIF
    ENDFUNC

    PROC main()
        VAR num item;
        VAR btnres button := resOK;
        VAR errnum flag;

        TPWrite "item " \Num:=ChooseItem(0);
        TPWrite "item " \Num:=ChooseItem(30);

        item := UIListView(\Result:=button, liMenu \BtnArray:=["Run", "Back"] \BreakFlag:=flag);
        IF flag = ERR_TP_NO_CLIENT TPWrite "flagged";
        TPWrite "item " \Num:=item;
        IF button = resUnkwn TPWrite "no button";
    ENDPROC
ENDMODULE
