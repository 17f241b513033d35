MODULE strfn_reverse
    ! Reverse a string with StrPart in a FOR loop with STEP -1.
    FUNC string reverse(string s)
        VAR string r := "";
        FOR i FROM StrLen(s) TO 1 STEP -1 DO
            r := r + StrPart(s, i, 1);
        ENDFOR
        RETURN r;
    ENDFUNC

    PROC main()
        TPWrite reverse("abcde");
        TPWrite reverse("Robotics");
        TPWrite "[" + reverse("") + "]";
        TPWrite "pal=" \Bool:=reverse("level") = "level";
    ENDPROC
ENDMODULE
