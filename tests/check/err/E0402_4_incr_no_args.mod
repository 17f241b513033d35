! expect: E0402 line 5
! Incr called without its argument
MODULE E0402_4
  PROC main()
    Incr;
  ENDPROC
ENDMODULE
