! expect: E0106 line 6
! an exponent E with no digits
MODULE E0106_2
  VAR num n;
  PROC main()
    n := 1.5E;
  ENDPROC
ENDMODULE
