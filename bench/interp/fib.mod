MODULE BenchFib
  ! Benchmark 1: naive recursive Fibonacci, fib(25) = 75025 (242785 calls).

  FUNC num fib(num n)
    IF n < 2 THEN
      RETURN n;
    ENDIF
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC

  PROC main()
    TPWrite "fib(25)=" \Num:=fib(25);
  ENDPROC
ENDMODULE
