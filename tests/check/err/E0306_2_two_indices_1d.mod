! expect: E0306 line 7
! two indices on a 1-dimensional array
MODULE E0306_2
  VAR num a{3};
  VAR num n;
  PROC main()
    n := a{1,2};
  ENDPROC
ENDMODULE
