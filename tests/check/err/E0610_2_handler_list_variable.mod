! expect: E0610 line 8
! a num variable in an ERROR number list
MODULE E0610_2
  VAR num n;
  VAR num d := 0;
  PROC main()
    n := 10 / d;
  ERROR (ERR_DIVZERO, d)
    TRYNEXT;
  ENDPROC
ENDMODULE
