! expect: E0304 line 4
! 4 elements for an array of 3
MODULE E0304_2
  VAR num arr{3} := [1,2,3,4];
ENDMODULE
