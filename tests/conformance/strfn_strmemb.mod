MODULE strfn_strmemb
    ! StrMemb: is the character at ChPos in Set (semantics 3.1 examples).
    PROC main()
        TPWrite "a=" \Bool:=StrMemb("Robotics", 2, "aeiou");
        TPWrite "b=" \Bool:=StrMemb("Robotics", 3, "aeiou");
        TPWrite "c=" \Bool:=StrMemb("a1", 2, STR_DIGIT);
        TPWrite "d=" \Bool:=StrMemb("a1", 1, STR_DIGIT);
        TPWrite "e=" \Bool:=StrMemb("Robotics", 1, STR_UPPER);
    ENDPROC
ENDMODULE
