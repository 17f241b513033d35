! expect: E0511 line 4
! a switch parameter without backslash
MODULE E0511_1
  PROC run(switch fast)
    TPWrite "run";
  ENDPROC
ENDMODULE
