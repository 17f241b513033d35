MODULE recur_gcd
    ! Euclid's algorithm, recursive, with MOD.
    FUNC num gcd(num a, num b)
        IF b = 0 RETURN a;
        RETURN gcd(b, a MOD b);
    ENDFUNC

    PROC main()
        TPWrite "gcd(48,18)=" \Num:=gcd(48, 18);
        TPWrite "gcd(17,5)=" \Num:=gcd(17, 5);
        TPWrite "gcd(100,75)=" \Num:=gcd(100, 75);
        TPWrite "lcm(4,6)=" \Num:=4 * 6 DIV gcd(4, 6);
    ENDPROC
ENDMODULE
