MODULE strfn_valtostr
    ! ValToStr writes bool as TRUE/FALSE and integers without decimals.
    PROC main()
        VAR num n;
        VAR bool b;
        TPWrite ValToStr(TRUE);
        TPWrite ValToStr(FALSE);
        TPWrite ValToStr(42);
        TPWrite ValToStr(-7);
        TPWrite ValToStr(0);
        n := 6 * 7;
        TPWrite "n=" + ValToStr(n);
        b := 1 > 2;
        TPWrite "b=" + ValToStr(b);
        TPWrite "len=" \Num:=StrLen(ValToStr(12345));
    ENDPROC
ENDMODULE
