MODULE argname_basic
    ! ArgName (manual: "ArgName - Gets argument name"): the name of the original data
    ! object behind a parameter, or of a data object named directly. For an element
    ! or a component the whole data object's name is given. Module data are named as
    ! declared, whatever the letter case of the argument.
    VAR num chales := 5;
    CONST num limit := 3;
    PERS num counter := 7;
    VAR pos target := [1, 2, 3];
    VAR num table{3} := [10, 20, 30];

    PROC main()
        VAR num here := 1;
        TPWrite "direct " + ArgName(chales);
        TPWrite "case " + ArgName(CHALES);
        TPWrite "const " + ArgName(limit);
        TPWrite "pers " + ArgName(counter);
        TPWrite "local " + ArgName(here);
        TPWrite "component " + ArgName(target.x);
        TPWrite "element " + ArgName(table{2});
        TPWrite "named " + ArgName(Parameter:=limit);
        TPWrite "array " + ArgName(table);
        ! An IN parameter still refers back to the data object passed for it.
        show chales;
        show table{3};
        show here;
        ! Through a chain of parameters: the original data object, not `parameter1`.
        outer chales;
        outer target.y;
        inout_name counter;
        TPWrite "func " + name_of(limit);
        optional \a:=target.z;
        forward \b:=counter;
        %"show"% limit;
        arrays table;
    ENDPROC

    PROC arrays(num a{*})
        TPWrite "array parameter " + ArgName(a);
    ENDPROC

    PROC show(num par1)
        TPWrite "Argument name " + ArgName(par1) + " with value " \Num:=par1;
    ENDPROC

    PROC outer(num parameter1)
        middle parameter1;
    ENDPROC

    PROC middle(num p)
        inner p;
    ENDPROC

    PROC inner(num par1)
        TPWrite "inner " + ArgName(par1);
    ENDPROC

    PROC inout_name(INOUT num x)
        TPWrite "inout " + ArgName(x);
    ENDPROC

    FUNC string name_of(num value)
        RETURN ArgName(value);
    ENDFUNC

    PROC optional(\num a)
        IF Present(a) TPWrite "optional " + ArgName(a);
    ENDPROC

    ! A conditional argument passes the caller's own argument on.
    PROC forward(\num b)
        optional \a?b;
    ENDPROC
ENDMODULE
