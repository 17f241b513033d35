! expect: E0127 line 4
! a 4-dimensional module variable
MODULE E0127_1
  VAR num grid{2,2,2,2};
ENDMODULE
