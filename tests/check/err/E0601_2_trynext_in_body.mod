! expect: E0601 line 7
! TRYNEXT in the routine body
MODULE E0601_2
  VAR num n;
  PROC main()
    n := 1;
    TRYNEXT;
  ENDPROC
ENDMODULE
