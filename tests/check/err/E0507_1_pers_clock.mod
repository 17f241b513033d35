! expect: E0507 line 4
! a PERS of the non-value type clock
MODULE E0507_1
  PERS clock c;
ENDMODULE
