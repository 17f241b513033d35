MODULE scope_local_decls
    ! LOCAL module data and routines (manual 1.1.5 and 1.2.2, scope): usable
    ! inside their module; routine data hides module data of the same name.
    LOCAL VAR num counter := 5;
    LOCAL CONST string PREFIX := "id-";
    VAR num shared := 1;

    LOCAL FUNC string label(num n)
        RETURN PREFIX + ValToStr(n);
    ENDFUNC

    LOCAL PROC bump()
        counter := counter + 1;
    ENDPROC

    PROC main()
        VAR num shared := 100;
        bump;
        bump;
        TPWrite label(counter);
        TPWrite "shared=" \Num:=shared;
    ENDPROC
ENDMODULE
