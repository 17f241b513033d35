! expect: E0211 line 7
! a procedure name used as a parameter type
MODULE E0211_2
  PROC helper()
    TPWrite "helper";
  ENDPROC
  PROC run(helper h)
    TPWrite "run";
  ENDPROC
ENDMODULE
