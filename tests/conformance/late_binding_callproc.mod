MODULE late_binding_callproc
    ! Arguments a late-bound procedure cannot take raise ERR_CALLPROC when the call
    ! runs (RAPID instructions manual, ProcCall: "procedure call error (syntax error,
    ! not procedure) at run time (late binding)"), which a handler can catch.
    PROC greet(num a \num opt \switch loud)
        TPWrite "a=" \Num:=a;
    ENDPROC

    PROC try(num which)
        VAR string name := "greet";
        TEST which
        CASE 1:
            ! no parameter of that name
            % name % 1 \other:=2;
        CASE 2:
            ! a value for a switch
            % name % 1 \loud:=2;
        CASE 3:
            ! the required argument missing
            % name % \opt:=2;
        CASE 4:
            ! one argument too many
            % name % 1, 2;
        CASE 5:
            ! a required parameter written as optional
            % name % \a:=1;
        CASE 6:
            ! the same parameter twice
            % name % 1 \opt:=2 \opt:=3;
        ENDTEST
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_CALLPROC THEN
            TPWrite "callproc " \Num:=which;
            RETURN;
        ENDIF
    ENDPROC

    PROC main()
        FOR i FROM 1 TO 6 DO
            try i;
        ENDFOR
        % "greet" % 5 \loud;
    ENDPROC
ENDMODULE
