MODULE lex_case_insensitive
    ! RAPID is not case-sensitive (manual 1.1.1): names and keywords may be
    ! written in any mix of cases.
    VAR num Counter := 1;

    proc Bump()
        COUNTER := counter + 1;
    endproc

    PROC main()
        bump;
        BUMP;
        if counter = 3 then
            tpwrite "counter=" \num:=CoUnTeR;
        endif
        TPWRITE "ok=" \BOOL:=true;
    ENDPROC
ENDMODULE
