MODULE BenchVarCall
  ! Benchmark 6: 10^6 calls of a PROC that increments its VAR num argument
  ! (two counters, so each printed value stays at 500000).

  PROC incr(VAR num x)
    x := x + 1;
  ENDPROC

  PROC main()
    VAR num a := 0;
    VAR num b := 0;
    FOR i FROM 1 TO 500000 DO
      incr a;
      incr b;
    ENDFOR
    TPWrite "varcall a=" \Num:=a;
    TPWrite "varcall b=" \Num:=b;
  ENDPROC
ENDMODULE
