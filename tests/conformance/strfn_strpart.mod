MODULE strfn_strpart
    ! StrPart(Str, ChPos, Len): Len characters from position ChPos (1-based).
    PROC main()
        VAR string s := "Robotics";
        TPWrite StrPart(s, 1, 5);
        TPWrite StrPart(s, 6, 3);
        TPWrite StrPart(s, 8, 1);
        TPWrite StrPart(s, 1, 8);
        TPWrite StrPart(s, 3, 2) + StrPart(s, 1, 2);
        TPWrite StrPart("IRB 6400", 5, 4);
    ENDPROC
ENDMODULE
