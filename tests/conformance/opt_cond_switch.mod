MODULE opt_cond_switch
    ! A switch passed on conditionally through two levels.
    PROC inner(\switch fast)
        IF Present(fast) THEN
            TPWrite "fast";
        ELSE
            TPWrite "slow";
        ENDIF
    ENDPROC

    PROC middle(\switch fast)
        inner \fast?fast;
    ENDPROC

    PROC outer(\switch fast)
        middle \fast?fast;
    ENDPROC

    PROC main()
        outer \fast;
        outer;
    ENDPROC
ENDMODULE
