! expect: E0312 line 4
! a negative dimension
MODULE E0312_4
  VAR num a{-1};
ENDMODULE
