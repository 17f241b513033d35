MODULE BenchStartup
  ! Benchmark 0: start-up floor. Prints one line; measures process start, reading and
  ! checking the module, and running a trivial main.

  PROC main()
    TPWrite "startup ok=" \Num:=1;
  ENDPROC
ENDMODULE
