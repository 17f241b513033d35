MODULE late_binding_optional
    ! A late-bound call takes the same arguments as a call written with the
    ! procedure's name (manual 1.3.4): named required arguments, optional
    ! arguments written with \, switches, conditional arguments, in any order
    ! the rules allow. They are matched to the parameters when the call runs.
    PROC greet(num a \num opt \switch loud)
        IF Present(opt) TPWrite "opt=" \Num:=opt;
        IF Present(loud) TPWrite "loud";
        TPWrite "a=" \Num:=a;
    ENDPROC

    PROC bump(VAR num x \num by | switch twice)
        IF Present(by) THEN
            x := x + by;
        ELSEIF Present(twice) THEN
            x := x + 2;
        ELSE
            x := x + 1;
        ENDIF
    ENDPROC

    PROC relay(string name \num opt)
        ! passes its own optional parameter on only when it was given
        % name % 9 \opt?opt;
    ENDPROC

    PROC main()
        VAR string name := "greet";
        VAR num n := 0;
        % name % 1;
        % name % 2 \opt:=5;
        % name % 3 \loud;
        % "gre" + "et" % a:=4 \opt:=6 \loud;
        % name % \opt:=7, 8;
        name := "bump";
        % name % n;
        % name % n \by:=10;
        % name % n \twice;
        TPWrite "n=" \Num:=n;
        relay "greet";
        relay "greet" \opt:=3;
    ENDPROC
ENDMODULE
