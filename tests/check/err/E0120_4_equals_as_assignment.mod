! expect: E0120 line 6
! '=' is not the assignment operator
MODULE E0120_4
  VAR num n;
  PROC main()
    n = 5;
  ENDPROC
ENDMODULE
