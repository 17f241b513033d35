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
        VAR dnum k := 1000;
        f := fact(15);
        ! 1307674368000 in groups of three digits: 1307 674 368 000
        TPWrite "g1=" \Dnum:=f DIV (k * k * k);
        TPWrite "g2=" \Dnum:=(f DIV (k * k)) MOD k;
        TPWrite "g3=" \Dnum:=(f DIV k) MOD k;
        TPWrite "g4=" \Dnum:=f MOD k;
        TPWrite "ratio=" \Dnum:=fact(15) / fact(13);
    ENDPROC
ENDMODULE
