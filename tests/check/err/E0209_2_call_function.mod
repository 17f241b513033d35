! expect: E0209 line 8
! a FUNC called like a procedure
MODULE E0209_2
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC
  PROC main()
    twice 3;
  ENDPROC
ENDMODULE
