MODULE param_func_var
    ! A FUNC may have VAR parameters and change the caller's variable
    ! (manual 1.3.4, parameters).
    FUNC num nextId(VAR num counter)
        counter := counter + 1;
        RETURN counter * 10;
    ENDFUNC

    PROC main()
        VAR num c := 0;
        VAR num id;
        id := nextId(c);
        TPWrite "id=" \Num:=id;
        id := nextId(c);
        TPWrite "id=" \Num:=id;
        TPWrite "c=" \Num:=c;
    ENDPROC
ENDMODULE
