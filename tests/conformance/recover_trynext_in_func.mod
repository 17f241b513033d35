MODULE recover_trynext_in_func
    ! TRYNEXT in a FUNC handler continues inside the FUNC, which then
    ! returns normally.
    FUNC num average(num a{*})
        VAR num sum := 0;
        VAR num avg := 0;
        FOR i FROM 1 TO Dim(a, 1) DO
            sum := sum + a{i};
        ENDFOR
        avg := sum / (Dim(a, 1) - 3);
        RETURN avg;
    ERROR
        TPWrite "no average";
        TRYNEXT;
    ENDFUNC

    PROC main()
        VAR num three{3} := [1, 2, 3];
        VAR num five{5} := [2, 4, 6, 8, 10];
        TPWrite "avg=" \Num:=average(five);
        TPWrite "avg=" \Num:=average(three);
    ENDPROC
ENDMODULE
