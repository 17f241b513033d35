MODULE for_bounds_once
    ! From, To and Step are evaluated once, when the loop starts (semantics 5):
    ! changing n inside the body does not change the number of passes.
    PROC main()
        VAR num n := 3;
        VAR num st := 1;
        VAR num passes := 0;
        FOR i FROM 1 TO n STEP st DO
            n := n + 1;
            st := 5;
            passes := passes + 1;
        ENDFOR
        TPWrite "passes=" \Num:=passes;
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
