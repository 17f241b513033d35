MODULE strfn_count_members
    ! Count characters of a set with StrMemb.
    FUNC num countIn(string s, string chars)
        VAR num n := 0;
        ! STEP 1 given: for "" the loop must not run (without STEP,
        ! FROM 1 TO 0 would count down, semantics 5)
        FOR i FROM 1 TO StrLen(s) STEP 1 DO
            IF StrMemb(s, i, chars) n := n + 1;
        ENDFOR
        RETURN n;
    ENDFUNC

    PROC main()
        TPWrite "vowels=" \Num:=countIn("Robotics", "aeiou");
        TPWrite "digits=" \Num:=countIn("a1b22c333", STR_DIGIT);
        TPWrite "upper=" \Num:=countIn("IRB 6400 ABB", STR_UPPER);
        TPWrite "none=" \Num:=countIn("", STR_DIGIT);
    ENDPROC
ENDMODULE
