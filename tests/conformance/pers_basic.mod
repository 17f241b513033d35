MODULE pers_basic
    ! A PERS keeps its value between routine calls; it starts from the value
    ! in its declaration (manual 1.2.2, persistent declarations).
    PERS num count := 0;
    PERS string lastmsg := "none";

    PROC tick(string msg)
        count := count + 1;
        lastmsg := msg;
    ENDPROC

    PROC main()
        TPWrite "start=" \Num:=count;
        TPWrite "msg=" + lastmsg;
        tick "one";
        tick "two";
        tick "three";
        TPWrite "count=" \Num:=count;
        TPWrite "msg=" + lastmsg;
    ENDPROC
ENDMODULE
