! expect: E0312 line 4
! a non-integer dimension
MODULE E0312_3
  VAR num a{2.5};
ENDMODULE
