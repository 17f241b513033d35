MODULE arrparam_sizes
    ! The same open-array FUNC called with arrays of different sizes.
    FUNC num maxOf(num a{*})
        VAR num m;
        m := a{1};
        ! STEP 1 given: for a one-element array the loop must not run
        ! (without STEP, FROM 2 TO 1 would count down, semantics 5)
        FOR i FROM 2 TO Dim(a, 1) STEP 1 DO
            IF a{i} > m m := a{i};
        ENDFOR
        RETURN m;
    ENDFUNC

    FUNC num count(num a{*})
        RETURN Dim(a, 1);
    ENDFUNC

    PROC main()
        VAR num three{3} := [4, 9, 2];
        VAR num five{5} := [-3, -1, -7, -2, -9];
        VAR num one{1} := [42];
        TPWrite "max3=" \Num:=maxOf(three);
        TPWrite "max5=" \Num:=maxOf(five);
        TPWrite "max1=" \Num:=maxOf(one);
        TPWrite "n=" \Num:=count(three) + count(five) + count(one);
    ENDPROC
ENDMODULE
