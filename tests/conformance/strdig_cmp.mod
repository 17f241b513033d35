MODULE strdig_cmp
    ! StrDigCmp compares digit strings as numbers, not as text (a stringdig holds 0 to
    ! 4294967295; errnos as in crates/rapid-vm/src/builtins/strdig.rs, uncertain).
    PROC bad(string s1, string s2)
        VAR bool b;
        b := StrDigCmp(s1, LT, s2);
        TPWrite "no error";
    ERROR
        IF ERRNO = ERR_INT_NOTVAL THEN
            TPWrite "'" + s1 + "' '" + s2 + "': ERR_INT_NOTVAL";
        ELSEIF ERRNO = ERR_INT_MAXVAL THEN
            TPWrite "'" + s1 + "' '" + s2 + "': ERR_INT_MAXVAL";
        ELSE
            TPWrite "another error";
        ENDIF
        RETURN;
    ENDPROC

    PROC main()
        ! As text "99999" > "100000"; as numbers it is smaller.
        TPWrite "lt " \Bool:=StrDigCmp("99999", LT, "100000");
        TPWrite "lteq " \Bool:=StrDigCmp("7", LTEQ, "7");
        TPWrite "eq leading zeros " \Bool:=StrDigCmp("0042", EQ, "42");
        TPWrite "noteq " \Bool:=StrDigCmp("42", NOTEQ, "42");
        TPWrite "gteq " \Bool:=StrDigCmp("10", GTEQ, "9");
        TPWrite "gt at the limit " \Bool:=StrDigCmp("4294967295", GT, "4294967294");
        TPWrite "gt false " \Bool:=StrDigCmp("0", GT, "0");
        bad "12a", "1";
        bad "1", "";
        bad "-1", "1";
        bad "4294967296", "1";
        bad "1", "99999999999";
    ENDPROC
ENDMODULE
