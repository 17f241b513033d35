MODULE strfn_strorder
    ! StrOrder: TRUE when Str1 sorts before Str2 in the order of Order; a
    ! prefix sorts first (semantics 3.1).
    PROC main()
        TPWrite "a=" \Bool:=StrOrder("FIRST", "SECOND", STR_UPPER);
        TPWrite "b=" \Bool:=StrOrder("SECOND", "FIRST", STR_UPPER);
        TPWrite "c=" \Bool:=StrOrder("AB", "ABC", STR_UPPER);
        TPWrite "d=" \Bool:=StrOrder("ABC", "AB", STR_UPPER);
        ! the order is that of the Order string, not of the alphabet
        TPWrite "e=" \Bool:=StrOrder("A", "B", "BA");
    ENDPROC
ENDMODULE
