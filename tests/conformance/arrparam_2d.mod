MODULE arrparam_2d
    ! Open 2-D array parameters take the size of the argument (manual 1.1.5).
    FUNC num total(num m{*, *})
        VAR num s := 0;
        FOR i FROM 1 TO Dim(m, 1) DO
            FOR j FROM 1 TO Dim(m, 2) DO
                s := s + m{i, j};
            ENDFOR
        ENDFOR
        RETURN s;
    ENDFUNC

    PROC fill(VAR num pallet{*, *})
        FOR i FROM 1 TO Dim(pallet, 1) DO
            FOR j FROM 1 TO Dim(pallet, 2) DO
                pallet{i, j} := i * j;
            ENDFOR
        ENDFOR
    ENDPROC

    PROC main()
        VAR num a{2, 3} := [[1, 2, 3], [4, 5, 6]];
        VAR num b{3, 2};
        TPWrite "total a=" \Num:=total(a);
        fill b;
        TPWrite "b32=" \Num:=b{3, 2};
        TPWrite "total b=" \Num:=total(b);
    ENDPROC
ENDMODULE
