MODULE str_predefined
    ! Predefined string data (manual 1.19, semantics 2.5).
    PROC main()
        TPWrite STR_DIGIT;
        TPWrite "digits=" \Num:=StrLen(STR_DIGIT);
        TPWrite "empty=" \Num:=StrLen(stEmpty);
        TPWrite StrPart(STR_UPPER, 1, 26);
        TPWrite StrPart(STR_LOWER, 1, 26);
    ENDPROC
ENDMODULE
