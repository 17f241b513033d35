MODULE recur_mutual
    ! Mutual recursion between two FUNCs.
    FUNC bool isEven(num n)
        IF n = 0 RETURN TRUE;
        RETURN isOdd(n - 1);
    ENDFUNC

    FUNC bool isOdd(num n)
        IF n = 0 RETURN FALSE;
        RETURN isEven(n - 1);
    ENDFUNC

    PROC main()
        TPWrite "even10=" \Bool:=isEven(10);
        TPWrite "odd7=" \Bool:=isOdd(7);
        TPWrite "even7=" \Bool:=isEven(7);
        TPWrite "odd0=" \Bool:=isOdd(0);
    ENDPROC
ENDMODULE
