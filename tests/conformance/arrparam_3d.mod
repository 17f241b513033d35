MODULE arrparam_3d
    ! Open 3-D array parameter with Dim on each dimension.
    FUNC num cells(num c{*, *, *})
        RETURN Dim(c, 1) * Dim(c, 2) * Dim(c, 3);
    ENDFUNC

    PROC mark(VAR bool c{*, *, *}, num i, num j, num k)
        c{i, j, k} := TRUE;
    ENDPROC

    PROC main()
        VAR num box{2, 3, 4};
        VAR bool seen{2, 2, 2};
        VAR num n := 0;
        TPWrite "cells=" \Num:=cells(box);
        mark seen, 2, 1, 2;
        mark seen, 1, 1, 1;
        FOR i FROM 1 TO 2 DO
            FOR j FROM 1 TO 2 DO
                FOR k FROM 1 TO 2 DO
                    IF seen{i, j, k} n := n + 1;
                ENDFOR
            ENDFOR
        ENDFOR
        TPWrite "marked=" \Num:=n;
        TPWrite "s212=" \Bool:=seen{2, 1, 2};
    ENDPROC
ENDMODULE
