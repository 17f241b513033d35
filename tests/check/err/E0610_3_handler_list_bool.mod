! expect: E0610 line 7
! a bool in an ERROR number list
MODULE E0610_3
  VAR num n;
  PROC main()
    n := 1;
  ERROR (ERR_DIVZERO, TRUE)
    TRYNEXT;
  ENDPROC
ENDMODULE
