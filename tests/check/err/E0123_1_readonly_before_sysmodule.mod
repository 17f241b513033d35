! expect: E0123 line 3
! attributes out of order: SYSMODULE must come first
MODULE E0123_1 (READONLY, SYSMODULE)
  VAR num n;
ENDMODULE
