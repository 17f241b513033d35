MODULE num_kernel_paths
    ! num assignments and conditions over num data run as kernels in f32 registers;
    ! whenever a kernel cannot give the answer (an error would arise, an operand is
    ! not a plain num), the statement's general code runs and raises the error. The
    ! results must be those of manual 1.3 either way.
    VAR num g := 10;
    VAR num arr{3} := [1, 2, 3];
    PERS num p := 4;
    VAR num zero := 0;
    VAR num c;

    PROC bump(VAR num x, INOUT num y)
        ! Targets and operands reached through references.
        x := x * 2 + y;
        y := -y + 1;
    ENDPROC

    PROC bump_pers(PERS num q)
        q := q * 10 + 1;
    ENDPROC

    PROC opt(\num o)
        VAR num r;
        r := o + 1;
        TPWrite "opt " \Num:=r;
    ERROR
        IF ERRNO = ERR_NOTPRES TPWrite "ERR_NOTPRES";
        RETURN;
    ENDPROC

    PROC div_zero()
        c := g / zero + 1;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_DIVZERO TPWrite "ERR_DIVZERO";
        RETURN;
    ENDPROC

    PROC read_outside(num k)
        c := arr{k} * 2;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_OUTOFBND TPWrite "read ERR_OUTOFBND";
        RETURN;
    ENDPROC

    PROC write_outside(num k)
        arr{k} := g * 2;
        TPWrite "not reached";
    ERROR
        IF ERRNO = ERR_OUTOFBND TPWrite "write ERR_OUTOFBND";
        RETURN;
    ENDPROC

    PROC mod_fraction()
        ! MOD takes integer operands only (manual 1.3.1).
        c := g MOD 0.5;
        TPWrite "not reached";
    ERROR
        TPWrite "MOD of a fraction raised an error";
        RETURN;
    ENDPROC

    PROC main()
        VAR num a := 7;
        VAR num b := 2;
        VAR num i := 0;
        c := (a + b) * 3 - a MOD b;
        TPWrite "c=" \Num:=c;
        c := a DIV b + -a MOD b;
        TPWrite "div/mod=" \Num:=c;
        arr{2} := arr{1} + arr{3} * g;
        TPWrite "arr2=" \Num:=arr{2};
        g := g + p * 2;
        TPWrite "g=" \Num:=g;
        bump a, b;
        TPWrite "bump a=" \Num:=a;
        TPWrite "bump b=" \Num:=b;
        bump_pers p;
        TPWrite "p=" \Num:=p;
        IF a > 10 AND NOT (b = 0) THEN
            TPWrite "cond1 TRUE";
        ELSEIF a < 0 THEN
            TPWrite "cond1 wrong branch";
        ELSE
            TPWrite "cond1 FALSE";
        ENDIF
        IF a < 0 THEN
            TPWrite "cond2 wrong branch";
        ELSEIF b < 0 AND a >= 16 THEN
            TPWrite "cond2 ELSEIF";
        ENDIF
        IF a < 0 XOR b < 0 TPWrite "xor TRUE";
        IF a < 0 OR b > 0 TPWrite "or wrong";
        WHILE i * i < 10 DO
            i := i + 1;
        ENDWHILE
        TPWrite "i=" \Num:=i;
        div_zero;
        read_outside 4;
        read_outside 1.5;
        write_outside 0;
        mod_fraction;
        opt;
        opt \o:=1;
        TPWrite "arr=" \Num:=arr{1} + arr{2} + arr{3};
    ENDPROC
ENDMODULE
