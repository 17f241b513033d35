MODULE strfn_strmatch
    ! StrMatch finds a pattern from ChPos; not found gives StrLen+1 (semantics 3.1).
    PROC main()
        TPWrite "a=" \Num:=StrMatch("Robotics", 1, "bo");
        TPWrite "b=" \Num:=StrMatch("Robotics", 4, "bo");
        TPWrite "c=" \Num:=StrMatch("abcabc", 2, "abc");
        TPWrite "d=" \Num:=StrMatch("abcabc", 1, "abc");
        TPWrite "e=" \Num:=StrMatch("abcabc", 1, "cab");
        TPWrite "f=" \Num:=StrMatch("abc", 1, "abcd");
    ENDPROC
ENDMODULE
