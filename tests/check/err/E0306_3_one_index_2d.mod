! expect: E0306 line 7
! one index on a 2-dimensional array
MODULE E0306_3
  VAR num m{2,2};
  VAR num n;
  PROC main()
    n := m{1};
  ENDPROC
ENDMODULE
