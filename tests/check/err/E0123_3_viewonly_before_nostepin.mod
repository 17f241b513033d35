! expect: E0123 line 3
! attributes out of order: NOSTEPIN comes before VIEWONLY
MODULE E0123_3 (VIEWONLY, NOSTEPIN)
  VAR num n;
ENDMODULE
