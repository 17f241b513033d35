MODULE sym_search
    ! SetDataSearch selects the task's module data of one type; GetNextSym hands the
    ! objects out in declaration order and then returns FALSE (docs/semantics.md).
    ! \Object is a regular expression that must match the whole name, in any letter case;
    ! \VarSym \PersSym \ConstSym choose storage classes (none: all); \InMod one module;
    ! \GlobalSym skips LOCAL data and \LocalSym the rest. Arrays of the type are found too
    ! (`regs` matches `reg[^0-4]`: s is not in 0-4).
    VAR num reg1 := 1;
    VAR num reg2 := 2;
    PERS num reg3 := 3;
    CONST num reg4 := 4;
    VAR num other := 5;
    LOCAL VAR num reg5 := 6;
    VAR string reg6 := "s";
    VAR num regs{2} := [7, 8];

    PROC main()
        VAR string name;
        VAR datapos block;
        VAR num value;
        VAR bool found;
        TPWrite "all num:";
        SetDataSearch "num";
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        TPWrite "again=" \Bool:=GetNextSym(name, block);
        TPWrite "REG[0-9] VAR:";
        SetDataSearch "num" \Object:="REG[0-9]" \VarSym;
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        TPWrite "PERS or CONST:";
        SetDataSearch "num" \PersSym \ConstSym;
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        TPWrite "local in module:";
        SetDataSearch "num" \InMod:="SYM_SEARCH" \LocalSym;
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        TPWrite "global reg.+:";
        SetDataSearch "num" \Object:="reg.+" \GlobalSym;
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        TPWrite "o|reg[^0-4]|x:";
        SetDataSearch "NUM" \Object:="o.*|reg[^0-4]|x" \InTask;
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        TPWrite "string:";
        SetDataSearch "string";
        WHILE GetNextSym(name, block) DO
            TPWrite name;
        ENDWHILE
        SetDataSearch "num" \InMod:="no_such_module";
        TPWrite "other module=" \Bool:=GetNextSym(name, block);
        SetDataSearch "robtarget";
        TPWrite "robtarget=" \Bool:=GetNextSym(name, block);
        ! The datapos reaches the LOCAL reg5 through GetDataVal/SetDataVal \Block.
        SetDataSearch "num" \Object:="reg5";
        found := GetNextSym(name, block);
        GetDataVal name \Block:=block, value;
        TPWrite name + "=" \Num:=value;
        SetDataVal name \Block:=block, 60;
        TPWrite "reg5=" \Num:=reg5;
    ENDPROC
ENDMODULE
