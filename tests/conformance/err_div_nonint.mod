MODULE err_div_nonint
    ! DIV needs integer operands (manual 1.3.1 note iii: non-integer operands
    ! are invalid). Which errno is raised is not known (ERR_INT_NOTVAL or
    ! ERR_NOTINTVAL, semantics 1.3), so only the unhandled stop is checked.
    PROC main()
        VAR num a := 7.5;
        VAR num b := 2;
        VAR num c := 1;
        TPWrite "before";
        c := a DIV b;
        TPWrite "after";
    ENDPROC
ENDMODULE
