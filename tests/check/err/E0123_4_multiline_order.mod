! expect: E0123 line 5
! attribute list over three lines: reported at the attribute that comes too late
MODULE E0123_4 (SYSMODULE,
                READONLY,
                NOSTEPIN)
  VAR num n;
ENDMODULE
