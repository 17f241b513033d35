! expect: E0121 line 8
! expect: E0120 line 12
! expect: E0201 line 15
! error recovery: a missing ENDIF, a syntax error and an undefined name in three routines
MODULE E0121_9
  VAR num n;
  PROC first()
    IF n > 0 THEN
      n := 0;
  ENDPROC
  PROC second()
    n := n *;
  ENDPROC
  PROC third()
    n := missing;
  ENDPROC
ENDMODULE
