MODULE ui_numtune_breakflag
    ! UINumTune / UIDnumTune: with \BreakFlag and no answer the value shown,
    ! InitValue, is returned; without \BreakFlag the error goes to the handler.
    PERS num nSpeed := 100;

    PROC main()
        VAR errnum flag;
        VAR dnum dCount := 5;

        nSpeed := UINumTune(\Header:="Speed" \Message:="Tune the speed", nSpeed, 10 \MinValue:=50 \MaxValue:=150 \MaxTime:=5 \BreakFlag:=flag);
        IF flag = ERR_TP_MAXTIME TPWrite "timeout";
        TPWrite "speed " \Num:=nSpeed;

        dCount := UIDnumTune(\MsgArray:=["Parts", "per box"], dCount, 1 \BreakFlag:=flag);
        IF flag = ERR_TP_NO_CLIENT TPWrite "no client";
        TPWrite "count " \Dnum:=dCount;

        dCount := UIDnumTune(\Message:="Parts", 7, 1);
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_TP_NO_CLIENT THEN
            TPWrite "handled; count still " \Dnum:=dCount;
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
