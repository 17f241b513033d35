MODULE strdig_calc
    ! StrDigCalc on digit strings up to 4294967295; results have no leading zeros.
    ! Errnos as in crates/rapid-vm/src/builtins/strdig.rs (uncertain).
    PROC calc(string s1, opcalc op, string s2)
        TPWrite s1 + " op" + NumToStr(op, 0) + " " + s2 + " = " + StrDigCalc(s1, op, s2);
    ERROR
        IF ERRNO = ERR_CALC_OVERFLOW THEN
            TPWrite s1 + " op" + NumToStr(op, 0) + " " + s2 + ": ERR_CALC_OVERFLOW";
        ELSEIF ERRNO = ERR_CALC_NEG THEN
            TPWrite s1 + " op" + NumToStr(op, 0) + " " + s2 + ": ERR_CALC_NEG";
        ELSEIF ERRNO = ERR_CALC_DIVZERO THEN
            TPWrite s1 + " op" + NumToStr(op, 0) + " " + s2 + ": ERR_CALC_DIVZERO";
        ELSEIF ERRNO = ERR_INT_NOTVAL THEN
            TPWrite s1 + " op" + NumToStr(op, 0) + " " + s2 + ": ERR_INT_NOTVAL";
        ELSE
            TPWrite "another error";
        ENDIF
        RETURN;
    ENDPROC

    PROC main()
        VAR stringdig big := "4294967290";
        ! OpAdd=1 OpSub=2 OpMult=3 OpDiv=4 OpMod=5 (catalogue data.rs).
        TPWrite "add " + StrDigCalc(big, OpAdd, "5");
        calc big, OpAdd, "6";
        calc "100", OpSub, "1";
        calc "1", OpSub, "2";
        calc "65536", OpMult, "65535";
        calc "65536", OpMult, "65536";
        calc "1000000007", OpDiv, "1000";
        calc "1000000007", OpMod, "1000";
        calc "5", OpDiv, "0";
        calc "5", OpMod, "0";
        calc "007", OpAdd, "0";
        calc "1.5", OpAdd, "1";
    ENDPROC
ENDMODULE
