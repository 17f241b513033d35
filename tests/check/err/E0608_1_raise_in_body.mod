! expect: E0608 line 7
! RAISE without a number in the body
MODULE E0608_1
  VAR num n;
  PROC main()
    n := 1;
    RAISE;
  ENDPROC
ENDMODULE
