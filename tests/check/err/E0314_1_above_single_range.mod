! expect: E0314 line 4
! 1E39 is beyond the single-precision range of num
MODULE E0314_1
  VAR num x := 1E39;
ENDMODULE
