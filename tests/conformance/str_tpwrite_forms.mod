MODULE str_tpwrite_forms
    ! TPWrite prints its text and then the optional value; TPErase prints
    ! nothing in this test harness.
    PROC main()
        TPErase;
        TPWrite "text only";
        TPWrite "" \Num:=5;
        TPWrite "";
        TPWrite "b=" \Bool:=TRUE;
        TPWrite "n=" \Num:=-12;
        TPErase;
        TPWrite "d=" \Dnum:=7;
        TPWrite "spaces " \Num:=1;
    ENDPROC
ENDMODULE
