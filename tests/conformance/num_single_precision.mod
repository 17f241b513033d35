MODULE num_single_precision
    ! num is an IEEE 754 single (semantics 2.1): 16777217 cannot be held,
    ! so 16777216 + 1 rounds back to 16777216 (round to nearest even).
    ! dnum is a double and holds it exactly.
    PROC main()
        VAR num n;
        VAR dnum d;
        n := 16777216;
        n := n + 1;
        IF n = 16777216 THEN
            TPWrite "num rounded";
        ELSE
            TPWrite "num exact";
        ENDIF
        d := 16777216;
        d := d + 1;
        IF d = 16777216 THEN
            TPWrite "dnum rounded";
        ELSE
            TPWrite "dnum exact";
        ENDIF
        TPWrite "dnum diff=" \Dnum:=d - 16777216;
    ENDPROC
ENDMODULE
