MODULE bool_default_assign
    ! An uninitialised bool is FALSE (manual 1.2.2); bool from comparisons.
    PROC main()
        VAR bool b;
        TPWrite "init=" \Bool:=b;
        b := 5 > 3;
        TPWrite "gt=" \Bool:=b;
        b := NOT b;
        TPWrite "not=" \Bool:=b;
        IF NOT b TPWrite "compact IF with NOT";
        b := b OR TRUE;
        IF b THEN
            TPWrite "b is TRUE";
        ENDIF
    ENDPROC
ENDMODULE
