! expect: E0601 line 7
! RETRY in the routine body
MODULE E0601_1
  VAR num n;
  PROC main()
    n := 1;
    RETRY;
  ENDPROC
ENDMODULE
