MODULE strfn_split_words
    ! Split a string at blanks with StrFind and StrPart. StrFind gives
    ! StrLen+1 when no blank is left (semantics 3.1).
    PROC main()
        VAR string s := "pick place home";
        VAR num start := 1;
        VAR num sp;
        VAR num len;
        len := StrLen(s);
        WHILE start <= len DO
            sp := StrFind(s, start, " ");
            TPWrite "word=" + StrPart(s, start, sp - start);
            start := sp + 1;
        ENDWHILE
        TPWrite "start=" \Num:=start;
    ENDPROC
ENDMODULE
