MODULE if_chain
    ! IF ... ELSEIF ... ELSE ... ENDIF (manual 1.5): the first TRUE branch runs.
    PROC classify(num n)
        IF n < 0 THEN
            TPWrite "negative";
        ELSEIF n = 0 THEN
            TPWrite "zero";
        ELSEIF n < 10 THEN
            TPWrite "small";
        ELSE
            TPWrite "large";
        ENDIF
    ENDPROC

    PROC main()
        VAR num m := -5;
        classify m;
        classify 0;
        classify 7;
        classify 10;
        classify 100;
    ENDPROC
ENDMODULE
