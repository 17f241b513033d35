! expect: E0120 line 6
! missing ';' - reported on the line of the token after which it belongs
MODULE E0120_1
  VAR num n;
  PROC main()
    n := 1
    n := 2;
  ENDPROC
ENDMODULE
