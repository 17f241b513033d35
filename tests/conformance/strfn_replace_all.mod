MODULE strfn_replace_all
    ! Replace every occurrence of a pattern using StrMatch and StrPart.
    FUNC string replaceAll(string s, string pat, string rep)
        VAR string r := "";
        VAR num at := 1;
        VAR num hit;
        hit := StrMatch(s, at, pat);
        WHILE hit <= StrLen(s) DO
            IF hit > at r := r + StrPart(s, at, hit - at);
            r := r + rep;
            at := hit + StrLen(pat);
            IF at > StrLen(s) THEN
                hit := StrLen(s) + 1;
            ELSE
                hit := StrMatch(s, at, pat);
            ENDIF
        ENDWHILE
        IF at <= StrLen(s) r := r + StrPart(s, at, StrLen(s) - at + 1);
        RETURN r;
    ENDFUNC

    PROC main()
        TPWrite replaceAll("a.b.c", ".", "::");
        TPWrite replaceAll("one two one", "one", "1");
        TPWrite replaceAll("xyz", "q", "-");
    ENDPROC
ENDMODULE
