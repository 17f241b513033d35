MODULE exit_in_loop
    ! EXIT inside a loop inside a FUNC.
    FUNC num firstOver(num limit)
        FOR i FROM 1 TO 10 DO
            TPWrite "i=" \Num:=i;
            IF i > limit EXIT;
        ENDFOR
        RETURN 0;
    ENDFUNC

    PROC main()
        VAR num r;
        r := firstOver(2);
        TPWrite "not reached";
    ENDPROC
ENDMODULE
