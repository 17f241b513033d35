MODULE param_inout_string
    ! INOUT string parameter used to build a result.
    PROC append(INOUT string s, string tail)
        IF s <> "" s := s + ",";
        s := s + tail;
    ENDPROC

    PROC main()
        VAR string list := "";
        append list, "a";
        append list, "b";
        append list, "c";
        TPWrite list;
    ENDPROC
ENDMODULE
