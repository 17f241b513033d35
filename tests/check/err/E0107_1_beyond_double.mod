! expect: E0107 line 4
! 1E400 is outside every IEEE 754 range (dnum context, so not E0314)
MODULE E0107_1
  VAR dnum big := 1E400;
ENDMODULE
