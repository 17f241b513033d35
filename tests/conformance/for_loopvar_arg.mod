MODULE for_loopvar_arg
    ! The loop variable can be read and passed as an IN argument.
    FUNC num square(num x)
        RETURN x * x;
    ENDFUNC

    PROC main()
        VAR num total := 0;
        FOR k FROM 1 TO 4 DO
            total := total + square(k);
        ENDFOR
        TPWrite "total=" \Num:=total;
    ENDPROC
ENDMODULE
