! expect: E0301 line 4
! a string initialiser for a num
MODULE E0301_1
  VAR num n := "text";
ENDMODULE
