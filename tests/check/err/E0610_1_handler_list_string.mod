! expect: E0610 line 7
! a string in an ERROR number list
MODULE E0610_1
  VAR num n;
  PROC main()
    n := 1;
  ERROR ("oops")
    TRYNEXT;
  ENDPROC
ENDMODULE
