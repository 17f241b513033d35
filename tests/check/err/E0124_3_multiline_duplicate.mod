! expect: E0124 line 5
! attribute list over three lines: reported at the second occurrence
MODULE E0124_3 (SYSMODULE,
                NOSTEPIN,
                NOSTEPIN)
  VAR num n;
ENDMODULE
