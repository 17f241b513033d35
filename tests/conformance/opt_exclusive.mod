MODULE opt_exclusive
    ! Mutually exclusive optional parameters (manual 1.1.5: routine3 and
    ! routine4); at most one of each group is passed.
    PROC routine3(\num exclude1 | num exclude2)
        VAR bool none := TRUE;
        IF Present(exclude1) THEN
            TPWrite "exclude1=" \Num:=exclude1;
            none := FALSE;
        ENDIF
        IF Present(exclude2) THEN
            TPWrite "exclude2=" \Num:=exclude2;
            none := FALSE;
        ENDIF
        IF none TPWrite "none";
    ENDPROC

    PROC routine4(\switch on | switch off)
        IF Present(off) THEN
            TPWrite "off";
        ELSEIF Present(on) THEN
            TPWrite "on";
        ELSE
            TPWrite "neither";
        ENDIF
    ENDPROC

    PROC main()
        routine3 \exclude1:=1;
        routine3 \exclude2:=2;
        routine3;
        routine4 \on;
        routine4 \off;
        routine4;
    ENDPROC
ENDMODULE
