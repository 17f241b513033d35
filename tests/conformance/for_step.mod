MODULE for_step
    ! FOR with STEP: the loop runs while the variable is within From..To.
    PROC main()
        VAR string s := "";
        FOR i FROM 0 TO 10 STEP 2 DO
            s := s + ValToStr(i) + " ";
        ENDFOR
        TPWrite s + "|";
        s := "";
        FOR i FROM 1 TO 10 STEP 3 DO
            s := s + ValToStr(i) + " ";
        ENDFOR
        TPWrite s + "|";
        s := "";
        FOR i FROM 1 TO 9 STEP 3 DO
            s := s + ValToStr(i) + " ";
        ENDFOR
        TPWrite s + "|";
    ENDPROC
ENDMODULE
