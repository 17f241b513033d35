MODULE goto_forward
    ! A forward GOTO skips statements.
    PROC main()
        VAR num x := 1;
        GOTO later;
        x := 2;
        TPWrite "skipped";
        later:
        TPWrite "x=" \Num:=x;
        IF x = 1 THEN
            GOTO tail;
        ENDIF
        TPWrite "skipped too";
        tail:
        TPWrite "end";
    ENDPROC
ENDMODULE
