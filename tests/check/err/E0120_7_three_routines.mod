! expect: E0120 line 8
! expect: E0120 line 11
! expect: E0120 line 14
! error recovery: three syntax errors in three routines, each reported
MODULE E0120_7
  VAR num n;
  PROC first()
    n := n +;
  ENDPROC
  PROC second()
    n = 3;
  ENDPROC
  PROC third()
    Add n 2;
  ENDPROC
ENDMODULE
