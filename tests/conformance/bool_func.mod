MODULE bool_func
    ! bool FUNCs and bool parameters.
    FUNC bool isEven(num n)
        RETURN n MOD 2 = 0;
    ENDFUNC

    FUNC bool implies(bool p, bool q)
        RETURN (NOT p) OR q;
    ENDFUNC

    PROC main()
        TPWrite "4 even " \Bool:=isEven(4);
        TPWrite "7 even " \Bool:=isEven(7);
        TPWrite "T->F " \Bool:=implies(TRUE, FALSE);
        TPWrite "F->F " \Bool:=implies(FALSE, FALSE);
        TPWrite "both " \Bool:=isEven(2) AND isEven(10);
    ENDPROC
ENDMODULE
