! expect: E0408 line 5
! a literal passed to Incr (INOUT)
MODULE E0408_1
  PROC main()
    Incr 5;
  ENDPROC
ENDMODULE
