MODULE arrparam_strings
    ! Open string array parameter.
    FUNC string joinAll(string parts{*}, string sep)
        VAR string r := "";
        FOR i FROM 1 TO Dim(parts, 1) DO
            IF i > 1 r := r + sep;
            r := r + parts{i};
        ENDFOR
        RETURN r;
    ENDFUNC

    PROC main()
        VAR string words{3} := ["red", "green", "blue"];
        VAR string two{2} := ["x", "y"];
        TPWrite joinAll(words, ", ");
        TPWrite joinAll(two, "-");
    ENDPROC
ENDMODULE
