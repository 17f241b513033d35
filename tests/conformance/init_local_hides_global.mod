MODULE init_local_hides_global
    ! Routine data hides module data of the same name (manual 1.2.2, scope).
    VAR num level := 1;

    PROC showGlobal()
        TPWrite "global=" \Num:=level;
    ENDPROC

    PROC main()
        VAR num level := 2;
        TPWrite "local=" \Num:=level;
        level := 20;
        showGlobal;
        TPWrite "local=" \Num:=level;
    ENDPROC
ENDMODULE
