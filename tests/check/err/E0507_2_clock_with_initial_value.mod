! expect: E0507 line 5
! a clock given an initial value
MODULE E0507_2
  VAR clock c1;
  VAR clock c2 := c1;
ENDMODULE
