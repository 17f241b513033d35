MODULE strfn_strlen
    ! StrLen counts characters (semantics 3.1).
    PROC main()
        VAR string s := "Robotics";
        TPWrite "a=" \Num:=StrLen("");
        TPWrite "b=" \Num:=StrLen(s);
        TPWrite "c=" \Num:=StrLen(STR_DIGIT);
        TPWrite "d=" \Num:=StrLen("IRB 6400");
        TPWrite "e=" \Num:=StrLen(s + s);
        TPWrite "f=" \Num:=StrLen("\41\42");
    ENDPROC
ENDMODULE
