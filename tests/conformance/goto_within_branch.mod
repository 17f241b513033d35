MODULE goto_within_branch
    ! A label inside an IF branch, reached by a GOTO in that same branch, and
    ! one inside a loop body reached from the same body.
    PROC main()
        VAR num k := 0;
        VAR num total := 0;
        IF TRUE THEN
            inner:
            k := k + 1;
            IF k < 3 GOTO inner;
            TPWrite "k=" \Num:=k;
        ENDIF
        FOR i FROM 1 TO 2 DO
            k := 0;
            body:
            k := k + 1;
            total := total + 1;
            IF k < 2 GOTO body;
        ENDFOR
        TPWrite "total=" \Num:=total;
    ENDPROC
ENDMODULE
