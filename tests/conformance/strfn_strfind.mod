MODULE strfn_strfind
    ! StrFind examples of semantics 3.1; "not found" gives StrLen+1.
    PROC main()
        TPWrite "a=" \Num:=StrFind("Robotics", 1, STR_DIGIT);
        TPWrite "b=" \Num:=StrFind("IRB 6400", 1, STR_WHITE);
        TPWrite "c=" \Num:=StrFind("Robotics", 1, "aeiou");
        TPWrite "d=" \Num:=StrFind("Robotics", 3, "aeiou");
        TPWrite "e=" \Num:=StrFind("IRB 6400", 1, STR_DIGIT);
        ! \NotInSet: first character that is not in the set
        TPWrite "f=" \Num:=StrFind("IRB 6400", 1, STR_UPPER \NotInSet);
        TPWrite "g=" \Num:=StrFind("1234a", 1, STR_DIGIT \NotInSet);
        TPWrite "h=" \Num:=StrFind("12345", 1, STR_DIGIT \NotInSet);
    ENDPROC
ENDMODULE
