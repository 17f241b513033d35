MODULE err_mod_nonint
    ! MOD with a non-integer right operand is invalid (manual 1.3.1 note iii).
    ! Errno unknown (semantics 1.3): only the unhandled stop is checked.
    PROC main()
        VAR num b := 2.5;
        VAR num c := 1;
        TPWrite "before";
        c := 7 MOD b;
        TPWrite "after";
    ENDPROC
ENDMODULE
