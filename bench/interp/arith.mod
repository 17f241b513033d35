MODULE BenchArith
  ! Benchmark 2: 10^7 iterations of num arithmetic (+ - * / MOD).
  ! Every value is an exact integer below 8388608, so single-precision num is exact.

  PROC main()
    VAR num acc := 1;
    VAR num chk := 0;
    VAR num h;
    FOR i FROM 1 TO 1000 DO
      FOR j FROM 1 TO 10000 DO
        acc := (acc * 7 + j + i) MOD 999983;
        h := (acc - acc MOD 4) / 4;
        chk := (chk + h) MOD 999983;
      ENDFOR
    ENDFOR
    TPWrite "arith acc=" \Num:=acc;
    TPWrite "arith chk=" \Num:=chk;
  ENDPROC
ENDMODULE
