! expect: E0120 line 6
! a binary operator without its right operand
MODULE E0120_2
  VAR num n;
  PROC main()
    n := n +;
  ENDPROC
ENDMODULE
