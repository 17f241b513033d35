MODULE strfn_strtoval
    ! StrToVal parses a RAPID literal into a variable and returns TRUE, or
    ! returns FALSE for text that does not fit the type (semantics 2.4).
    PROC main()
        VAR num n;
        VAR bool ok;
        VAR bool b;
        VAR pos p;
        ok := StrToVal("42", n);
        TPWrite "ok=" \Bool:=ok;
        TPWrite "n=" \Num:=n;
        ok := StrToVal("3.5", n);
        TPWrite "ok=" \Bool:=ok;
        TPWrite "n=" \Num:=n;
        ok := StrToVal("[1,2,3]", p);
        TPWrite "ok=" \Bool:=ok;
        TPWrite "py=" \Num:=p.y;
        ok := StrToVal("TRUE", b);
        TPWrite "ok=" \Bool:=ok;
        TPWrite "b=" \Bool:=b;
        ok := StrToVal("abc", n);
        TPWrite "bad=" \Bool:=ok;
    ENDPROC
ENDMODULE
