! expect: E0123 line 3
! NOVIEW may only stand alone or with SYSMODULE
MODULE E0123_2 (NOVIEW, NOSTEPIN)
  VAR num n;
ENDMODULE
