! expect: E0204 line 4
! an ALIAS of an undefined type
MODULE E0204_4
  ALIAS real myreal;
ENDMODULE
