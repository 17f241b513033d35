MODULE argname_errors
    ! ArgName raises ERR_ARGNAME when the argument is an expression, an optional
    ! parameter that was not passed, or a switch (manual, ArgName, error handling).
    ! With \ErrorNumber the error number is stored there instead (the variable is
    ! set to 0 first, so it is 0 after a success) and execution goes on.
    VAR num chales := 5;

    PROC main()
        VAR errnum e := 99;
        VAR string s;
        VAR string label;
        show 5;
        show chales + 1;
        show Abs(chales);
        outer 2 * chales;
        opt;
        opt \a:=chales;
        sw \s;
        fwd;
        s := ArgName(chales \ErrorNumber:=e);
        TPWrite "success " + s + " " \Num:=e;
        quiet 5;
        quiet chales;
        ! A handler that skips a failed ArgName with TRYNEXT keeps the default name.
        label := "L";
        TPWrite "describe " + describe(\n:=chales);
        TPWrite "describe " + describe(\n:=7);
        TPWrite "describe " + describe(\s:="x" + "y");
        TPWrite "describe " + describe(\s:=label);
    ENDPROC

    FUNC string describe(\num n | string s)
        VAR string name := "-";
        IF Present(n) name := ArgName(n);
        IF Present(s) name := ArgName(s);
        RETURN name;
    ERROR
        IF ERRNO = ERR_ARGNAME TRYNEXT;
        RAISE;
    ENDFUNC

    PROC show(num par1)
        TPWrite "name " + ArgName(par1);
    ERROR
        IF ERRNO = ERR_ARGNAME TPWrite "show: ERR_ARGNAME";
        RETURN;
    ENDPROC

    PROC outer(num p)
        show p;
    ENDPROC

    PROC opt(\num a)
        TPWrite "opt " + ArgName(a);
    ERROR
        IF ERRNO = ERR_ARGNAME TPWrite "opt: ERR_ARGNAME";
        RETURN;
    ENDPROC

    PROC sw(\switch s)
        TPWrite "sw " + ArgName(s);
    ERROR
        IF ERRNO = ERR_ARGNAME TPWrite "sw: ERR_ARGNAME";
        RETURN;
    ENDPROC

    ! A conditional argument for a parameter that was not passed passes nothing.
    PROC fwd(\num b)
        opt \a?b;
    ENDPROC

    PROC quiet(num v)
        VAR errnum e := 99;
        VAR string s := "unset";
        s := ArgName(v \ErrorNumber:=e);
        IF e = ERR_ARGNAME THEN
            TPWrite "quiet: ERR_ARGNAME stored, result """ + s + """";
        ELSE
            TPWrite "quiet " + s + " " \Num:=e;
        ENDIF
    ENDPROC
ENDMODULE
