MODULE arrparam_arrmul
    ! The manual's arrmul procedure (manual 1.1.5): open array parameter
    ! {*} and Dim (names are case-insensitive, so dim = Dim).
    PROC arrmul( VAR num array{*}, num factor)
        FOR index FROM 1 TO dim( array, 1 ) DO
            array{index} := array{index} * factor;
        ENDFOR
    ENDPROC

    PROC main()
        VAR num small{3} := [1, 2, 3];
        VAR num big{5} := [1, 1, 1, 1, 1];
        arrmul small, 10;
        arrmul big, 7;
        TPWrite "small=" + ValToStr(small{1}) + "," + ValToStr(small{2}) + "," + ValToStr(small{3});
        TPWrite "big5=" \Num:=big{5};
        TPWrite "dim=" \Num:=Dim(big, 1);
    ENDPROC
ENDMODULE
