MODULE recover_trynext
    ! TRYNEXT continues with the statement after the one that failed
    ! (manual 1.12).
    PROC main()
        VAR num zero := 0;
        VAR num x := 1;
        VAR num y := 2;
        TPWrite "start";
        y := 10 / zero;
        TPWrite "after error";
        x := x + y;
        TPWrite "x=" \Num:=x;
    ERROR
        TPWrite "handler";
        TRYNEXT;
    ENDPROC
ENDMODULE
