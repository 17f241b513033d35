! expect: E0128 line 3
! a declaration before MODULE
VAR num early;
MODULE E0128_1
  VAR num n;
ENDMODULE
