! expect: E0314 line 6
! the literal 3.5E38 (negated by unary minus) exceeds 3.40282E38
MODULE E0314_2
  VAR num n;
  PROC main()
    n := -3.5E38;
  ENDPROC
ENDMODULE
