MODULE for_negative_step
    ! FOR with a negative STEP counts down to To inclusive.
    PROC main()
        VAR string s := "";
        FOR i FROM 5 TO 1 STEP -1 DO
            s := s + ValToStr(i);
        ENDFOR
        TPWrite s;
        s := "";
        FOR i FROM 10 TO 0 STEP -3 DO
            s := s + ValToStr(i) + ",";
        ENDFOR
        TPWrite s;
        s := "";
        FOR i FROM -1 TO -4 STEP -1 DO
            s := s + ValToStr(i);
        ENDFOR
        TPWrite s;
    ENDPROC
ENDMODULE
