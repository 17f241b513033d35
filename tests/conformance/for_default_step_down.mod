MODULE for_default_step_down
    ! Without STEP the step is +1, or -1 when From is larger than To
    ! (semantics 5, FOR; from the ABB FOR description).
    PROC main()
        VAR string s := "";
        FOR i FROM 3 TO 1 DO
            s := s + ValToStr(i);
        ENDFOR
        TPWrite s;
        s := "";
        FOR i FROM 1 TO 3 DO
            s := s + ValToStr(i);
        ENDFOR
        TPWrite s;
        s := "";
        FOR i FROM 2 TO 2 DO
            s := s + ValToStr(i);
        ENDFOR
        TPWrite s;
    ENDPROC
ENDMODULE
