MODULE exit_in_sub
    ! EXIT in a nested routine ends the whole program, not just the routine.
    PROC b()
        TPWrite "in b";
        EXIT;
        TPWrite "b after";
    ENDPROC

    PROC a()
        TPWrite "in a";
        b;
        TPWrite "a after";
    ENDPROC

    PROC main()
        TPWrite "in main";
        a;
        TPWrite "main after";
    ENDPROC
ENDMODULE
