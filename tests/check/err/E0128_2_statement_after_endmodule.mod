! expect: E0128 line 6
! a statement after ENDMODULE
MODULE E0128_2
  VAR num n;
ENDMODULE
n := 1;
