MODULE dnum_factorial
    ! 15! = 1307674368000 is exact in dnum; checked through DIV/MOD.
    FUNC dnum fact(num n)
        VAR dnum r := 1;
        FOR i FROM 2 TO n DO
            r := r * i;
        ENDFOR
        RETURN r;
    ENDFUNC

    PROC main()
        VAR dnum f;
        VAR dnum m := 1000000;
        f := fact(15);
        ! 1307674368000 = 1307674 * 10^6 + 368000
        TPWrite "high=" \Dnum:=f DIV m;
        TPWrite "low=" \Dnum:=f MOD m;
        TPWrite "ratio=" \Dnum:=fact(15) / fact(13);
    ENDPROC
ENDMODULE
