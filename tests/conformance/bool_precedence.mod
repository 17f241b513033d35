MODULE bool_precedence
    ! Priorities of manual 1.3.5: relational > AND > OR/XOR; OR and XOR have
    ! the same priority and go left to right. (NOT is always parenthesised:
    ! how far an unparenthesised NOT reaches is not certain, semantics 5.)
    PROC main()
        VAR bool a := TRUE;
        VAR bool b := TRUE;
        VAR bool c := TRUE;
        VAR bool d := FALSE;
        ! (a AND b) OR (c AND d) = TRUE; strictly left to right would be FALSE
        TPWrite "r1=" \Bool:=a AND b OR c AND d;
        ! TRUE OR (FALSE AND FALSE)
        TPWrite "r2=" \Bool:=TRUE OR FALSE AND FALSE;
        ! (FALSE AND FALSE) OR TRUE
        TPWrite "r3=" \Bool:=FALSE AND FALSE OR TRUE;
        ! same level, left to right: (TRUE OR TRUE) XOR TRUE
        TPWrite "r4=" \Bool:=TRUE OR TRUE XOR TRUE;
        ! (TRUE XOR TRUE) OR TRUE
        TPWrite "r5=" \Bool:=TRUE XOR TRUE OR TRUE;
        ! TRUE XOR (TRUE AND FALSE)
        TPWrite "r6=" \Bool:=TRUE XOR TRUE AND FALSE;
        ! (1 < 2) AND (3 < 4)
        TPWrite "r7=" \Bool:=1 < 2 AND 3 < 4;
        ! arithmetic before relational before AND
        TPWrite "r8=" \Bool:=2 + 3 = 5 AND 2 * 3 = 6;
        TPWrite "r9=" \Bool:=NOT (TRUE AND FALSE);
        TPWrite "r10=" \Bool:=(NOT a) OR d;
    ENDPROC
ENDMODULE
