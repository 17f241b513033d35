! expect: E0106 line 6
! an exponent sign with no digits
MODULE E0106_3
  VAR num n;
  PROC main()
    n := 2E+;
  ENDPROC
ENDMODULE
