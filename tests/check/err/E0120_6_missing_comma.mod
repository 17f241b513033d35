! expect: E0120 line 6
! required arguments must be separated by commas
MODULE E0120_6
  VAR num n;
  PROC main()
    Add n 2;
  ENDPROC
ENDMODULE
