MODULE return_early
    ! RETURN leaves a PROC at once (manual 1.1.5, routine termination).
    PROC check(num v)
        IF v < 0 THEN
            TPWrite "negative, return";
            RETURN;
        ENDIF
        TPWrite "value " \Num:=v;
    ENDPROC

    FUNC num firstNeg(num a{*})
        FOR i FROM 1 TO Dim(a, 1) DO
            IF a{i} < 0 RETURN i;
        ENDFOR
        RETURN 0;
    ENDFUNC

    PROC main()
        VAR num arr{5} := [3, 4, -1, 5, -2];
        check 5;
        check -1;
        TPWrite "first negative at " \Num:=firstNeg(arr);
    ENDPROC
ENDMODULE
