! expect: E0128 line 6
! a whole routine after ENDMODULE: one report, at its first line
MODULE E0128_3
  VAR num n;
ENDMODULE
PROC extra()
  n := 2;
ENDPROC
