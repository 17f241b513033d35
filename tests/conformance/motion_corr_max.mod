MODULE motion_corr_max
    ! At most 5 correction generators are connected at once (manual, CorrCon:
    ! limitations); the sixth CorrCon stops execution (corr.rs, uncertain: the manual
    ! names no error for it). CorrDiscon frees a place.
    VAR corrdescr c{6};
    PROC main()
        FOR i FROM 1 TO 5 DO
            CorrCon c{i};
        ENDFOR
        TPWrite "five connected";
        CorrDiscon c{5};
        CorrCon c{6};
        TPWrite "five again";
        CorrCon c{5};
        TPWrite "not reached";
    ENDPROC
ENDMODULE
