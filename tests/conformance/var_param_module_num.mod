MODULE var_param_module_num
    ! A VAR (or INOUT) num parameter may refer to module-level data, to a routine's own data or
    ! to an array element; reads and writes through it reach that data (§1.1.5).
    VAR num total := 0;
    PERS num hits := 0;
    VAR num cells{3} := [1, 2, 3];

    PROC add(VAR num x, num amount)
        x := x + amount;
        x := 2 * x - x;
    ENDPROC

    ! A persistent is passed to an INOUT parameter (VAR accepts only variables).
    PROC bump(INOUT num x)
        x := x + 2;
    ENDPROC

    PROC main()
        VAR num own := 10;
        FOR i FROM 1 TO 1000 DO
            add total, i;
            add own, 1;
            bump hits;
        ENDFOR
        add cells{2}, 40;
        TPWrite "total " \Num:=total;
        TPWrite "own " \Num:=own;
        TPWrite "hits " \Num:=hits;
        TPWrite "cells " \Num:=cells{1} * 100 + cells{2} + cells{3};
    ENDPROC
ENDMODULE
