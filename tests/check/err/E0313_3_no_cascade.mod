! expect: E0313 line 5
! expect: E0313 line 6
! too large: one error each, none for the initial value or the uses (sizes unknown)
MODULE E0313_3
  VAR num a{2000000} := [1,2];
  VAR num b{1000,1000,1000};
  PROC main()
    a{5} := 1;
    b{1,2,3} := a{1};
  ENDPROC
ENDMODULE
