MODULE str_compare
    ! = and <> on strings; comparison is exact and case-sensitive.
    PROC main()
        VAR string s1 := "abc";
        VAR string s2 := "abc";
        TPWrite "a=" \Bool:=s1 = s2;
        TPWrite "b=" \Bool:=s1 <> s2;
        TPWrite "c=" \Bool:="abc" <> "abd";
        TPWrite "d=" \Bool:="abc" = "ABC";
        TPWrite "e=" \Bool:="" = stEmpty;
        TPWrite "f=" \Bool:="ab" = "abc";
        TPWrite "g=" \Bool:="a " = "a";
        s2 := s2 + "";
        TPWrite "h=" \Bool:=s1 = s2;
    ENDPROC
ENDMODULE
