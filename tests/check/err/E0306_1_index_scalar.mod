! expect: E0306 line 7
! indexing a num that is not an array
MODULE E0306_1
  VAR num k;
  VAR num n;
  PROC main()
    n := k{1};
  ENDPROC
ENDMODULE
