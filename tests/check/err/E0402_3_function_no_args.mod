! expect: E0402 line 6
! Abs called without its argument
MODULE E0402_3
  VAR num n;
  PROC main()
    n := Abs();
  ENDPROC
ENDMODULE
