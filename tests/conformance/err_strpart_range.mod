MODULE err_strpart_range
    ! StrPart beyond the end of the string is a run-time error (semantics
    ! 3.1); its errno is not known, so only the unhandled stop is checked.
    PROC main()
        VAR string s := "abc";
        VAR num len := 5;
        TPWrite StrPart(s, 2, 2);
        TPWrite StrPart(s, 2, len);
        TPWrite "not reached";
    ENDPROC
ENDMODULE
