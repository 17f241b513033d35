! expect: E0504 line 4
! a CONST without a value
MODULE E0504_1
  CONST num c;
ENDMODULE
