! expect: E0408 line 6
! an expression passed to Add's first (INOUT) parameter
MODULE E0408_2
  VAR num n;
  PROC main()
    Add n + 1, 2;
  ENDPROC
ENDMODULE
