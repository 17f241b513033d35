MODULE sym_errors
    ! Error paths of the symbol search (docs/semantics.md): a malformed \Object pattern
    ! raises ERR_ARGVALERR; GetNextSym before any SetDataSearch returns FALSE;
    ! GetDataVal \Block with a datapos GetNextSym never set, or a name its block cannot
    ! see, raises ERR_SYM_ACCESS; SetDataVal \Block on a constant raises ERR_SYM_ACCESS,
    ! with a value of another type ERR_SYMBOL_TYPE.
    VAR num count := 1;
    CONST num limit := 10;

    PROC main()
        VAR string name;
        VAR datapos block;
        VAR datapos unset;
        VAR num value;
        TPWrite "first=" \Bool:=GetNextSym(name, block);
        TPWrite "pattern: " + search("(count");
        TPWrite "bracket: " + search("[count");
        TPWrite "star: " + search("*count");
        TPWrite "good: " + search("count|limit");
        TPWrite "unset block: " + getval("count", unset);
        IF GetNextSym(name, block) TPWrite "next=" + name;
        TPWrite "unknown: " + getval("nothing", block);
        TPWrite "found: " + getval("count", block);
        TPWrite "constant: " + setval("limit", block, 5);
        TPWrite "type: " + setstr("count", block);
        TPWrite "count=" \Num:=count;
    ENDPROC

    FUNC string search(string pattern)
        SetDataSearch "num" \Object:=pattern;
        RETURN "ok";
    ERROR
        IF ERRNO = ERR_ARGVALERR RETURN "ERR_ARGVALERR";
    ENDFUNC

    FUNC string getval(string object, VAR datapos block)
        VAR num value;
        GetDataVal object \Block:=block, value;
        RETURN "ok " + NumToStr(value, 0);
    ERROR
        IF ERRNO = ERR_SYM_ACCESS RETURN "ERR_SYM_ACCESS";
    ENDFUNC

    FUNC string setval(string object, VAR datapos block, num value)
        SetDataVal object \Block:=block, value;
        RETURN "ok";
    ERROR
        IF ERRNO = ERR_SYM_ACCESS RETURN "ERR_SYM_ACCESS";
    ENDFUNC

    FUNC string setstr(string object, VAR datapos block)
        SetDataVal object \Block:=block, "text";
        RETURN "ok";
    ERROR
        IF ERRNO = ERR_SYMBOL_TYPE RETURN "ERR_SYMBOL_TYPE";
    ENDFUNC
ENDMODULE
