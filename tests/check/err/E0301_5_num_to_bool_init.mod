! expect: E0301 line 4
! a num initialiser for a bool
MODULE E0301_5
  VAR bool ok := 1;
ENDMODULE
