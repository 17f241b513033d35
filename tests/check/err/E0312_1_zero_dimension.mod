! expect: E0312 line 4
! an array dimension of 0
MODULE E0312_1
  VAR num a{0};
ENDMODULE
