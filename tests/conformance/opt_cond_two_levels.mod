MODULE opt_cond_two_levels
    ! Conditional arguments \v?v pass an optional parameter on only if it is
    ! present (manual 1.3.4), here down two levels of calls.
    PROC levelC(\num v)
        IF Present(v) THEN
            TPWrite "C got " \Num:=v;
        ELSE
            TPWrite "C got nothing";
        ENDIF
    ENDPROC

    PROC levelB(\num v)
        levelC \v?v;
    ENDPROC

    PROC levelA(\num v)
        levelB \v?v;
    ENDPROC

    PROC main()
        levelA \v:=5;
        levelA;
        levelB \v:=7;
    ENDPROC
ENDMODULE
