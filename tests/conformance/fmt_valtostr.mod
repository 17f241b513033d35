MODULE fmt_valtostr
    ! FORMAT-DEPENDENT. ValToStr uses the same num format and writes records
    ! as aggregates without blanks (semantics 2.4).
    PROC main()
        VAR pos p := [1, 0.5, 1000000];
        VAR extjoint ej := [9E9, 9E9, 9E9, 9E9, 9E9, 9E9];
        TPWrite ValToStr(1 / 3);
        TPWrite ValToStr(9E9);
        TPWrite ValToStr(p);
        TPWrite ValToStr(ej);
        TPWrite "v=" + ValToStr(2 / 3);
    ENDPROC
ENDMODULE
