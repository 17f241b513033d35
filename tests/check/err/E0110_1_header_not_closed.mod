! expect: E0110 line 3
! a file header (after the leading comments) that is never closed
%%%
  VERSION:1
  LANGUAGE:ENGLISH
MODULE E0110_1
  VAR num n;
ENDMODULE
