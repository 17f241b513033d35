! expect: E0312 line 7
! a dimension from a VAR (a CONST is fine)
MODULE E0312_2
  CONST num size := 4;
  VAR num n := 4;
  VAR num b{size};
  VAR num a{n};
ENDMODULE
