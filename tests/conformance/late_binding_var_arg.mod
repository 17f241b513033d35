MODULE late_binding_var_arg
    ! A late-bound call passes a VAR argument by reference like a normal call.
    PROC addOne(VAR num x)
        x := x + 1;
    ENDPROC

    PROC addTwo(VAR num x)
        x := x + 2;
    ENDPROC

    PROC main()
        VAR num n := 0;
        VAR string which := "addOne";
        % which % n;
        which := "addTwo";
        % which % n;
        % which % n;
        TPWrite "n=" \Num:=n;
    ENDPROC
ENDMODULE
