! expect: E0510 line 5
! ALIAS myalias other, where myalias is an alias
MODULE E0510_1
  ALIAS num myalias;
  ALIAS myalias other;
ENDMODULE
