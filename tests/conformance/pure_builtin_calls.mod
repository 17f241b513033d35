MODULE pure_builtin_calls
    ! StrLen and NumToStr called in a loop run through the fast loop's pure path;
    ! worked out from the manual (docs/semantics.md S2, S3, S7):
    !  - NumToStr(i / 3, 2) for i = 1..3: "0.33", "0.67", "1.00" (exactly 2 decimals);
    !    the joined text "0.33;0.67;1.00;" has 15 characters;
    !  - StrLen counts characters: "äöü" is 3 (6 bytes in UTF-8);
    !  - a Dec that is negative or not a whole number: ERR_ARGVALERR, twice.
    VAR string s := "";

    PROC main()
        FOR i FROM 1 TO 3 DO
            s := s + NumToStr(i / 3, 2) + ";";
        ENDFOR
        TPWrite s;
        TPWrite "len " \Num:=StrLen(s);
        s := "äöü";
        TPWrite "latin " \Num:=StrLen(s);
        s := NumToStr(5, -1);
        s := NumToStr(5, 1.5);
        TPWrite "end";
    ERROR
        IF ERRNO = ERR_ARGVALERR THEN
            TPWrite "ERR_ARGVALERR";
            TRYNEXT;
        ENDIF
    ENDPROC
ENDMODULE
