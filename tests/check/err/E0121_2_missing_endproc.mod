! expect: E0121 line 5
! PROC without ENDPROC; the next PROC starts
MODULE E0121_2
  VAR num n;
  PROC first()
    n := 1;
  PROC second()
    n := 2;
  ENDPROC
ENDMODULE
