! expect: E0206 line 11
! labels are routine-scoped
MODULE E0206_2
  VAR num n;
  PROC first()
  again:
    n := n + 1;
    IF n < 3 GOTO again;
  ENDPROC
  PROC second()
    GOTO again;
  ENDPROC
ENDMODULE
