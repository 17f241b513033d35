MODULE init_module_var_keeps
    ! Module variables are static (manual 1.2.2, storage class): values
    ! survive between routine calls.
    VAR num calls := 0;
    VAR string trail := "";

    PROC visit(string tag)
        calls := calls + 1;
        trail := trail + tag;
    ENDPROC

    PROC main()
        visit "a";
        visit "b";
        visit "c";
        TPWrite "calls=" \Num:=calls;
        TPWrite "trail=" + trail;
    ENDPROC
ENDMODULE
