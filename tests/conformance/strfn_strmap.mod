MODULE strfn_strmap
    ! StrMap replaces each character found in FromMap by the character at the
    ! same position in ToMap (semantics 3.1).
    PROC main()
        TPWrite StrMap("Robotics", STR_LOWER, STR_UPPER);
        TPWrite StrMap("ROBOT 1", STR_UPPER, STR_LOWER);
        TPWrite StrMap("1,5", ",", ".");
        TPWrite StrMap("abc", "ab", "xy");
        TPWrite StrMap("a-b-c", "-", "_");
    ENDPROC
ENDMODULE
