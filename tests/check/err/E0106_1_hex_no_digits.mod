! expect: E0106 line 6
! 0x with no hex digits
MODULE E0106_1
  VAR num n;
  PROC main()
    n := 0x;
  ENDPROC
ENDMODULE
