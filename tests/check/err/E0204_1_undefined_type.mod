! expect: E0204 line 4
! a variable of an undefined type
MODULE E0204_1
  VAR vector v;
ENDMODULE
