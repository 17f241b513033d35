! expect: E0107 line 5
! 1e400 in a num context: one error, the lexer's (no second E0314 suggesting a
! dnum, which cannot hold it either)
MODULE E0107_3
  VAR num x := 1e400;
ENDMODULE
