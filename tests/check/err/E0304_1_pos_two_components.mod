! expect: E0304 line 4
! a pos aggregate with 2 components
MODULE E0304_1
  VAR pos p := [1,2];
ENDMODULE
