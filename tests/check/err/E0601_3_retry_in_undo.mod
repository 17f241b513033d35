! expect: E0601 line 8
! RETRY in an UNDO handler
MODULE E0601_3
  VAR num n;
  PROC main()
    n := 1;
  UNDO
    RETRY;
  ENDPROC
ENDMODULE
