MODULE undo_in_func
    ! A FUNC may have an UNDO handler (manual 1.1.5 syntax); EXIT inside the
    ! FUNC runs its UNDO and then main's.
    FUNC num compute(num x)
        TPWrite "computing";
        IF x > 0 EXIT;
        RETURN x;
    UNDO
        TPWrite "undo compute";
    ENDFUNC

    PROC main()
        VAR num r;
        r := compute(0);
        TPWrite "r=" \Num:=r;
        r := compute(1);
        TPWrite "not reached";
    UNDO
        TPWrite "undo main";
    ENDPROC
ENDMODULE
