! expect: E0206 line 7
! GOTO to a label that does not exist
MODULE E0206_1
  VAR num n;
  PROC main()
    n := 0;
    GOTO nowhere;
  ENDPROC
ENDMODULE
