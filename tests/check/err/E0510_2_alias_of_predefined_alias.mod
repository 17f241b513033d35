! expect: E0510 line 4
! dionum is itself an alias of num
MODULE E0510_2
  ALIAS dionum mydio;
ENDMODULE
