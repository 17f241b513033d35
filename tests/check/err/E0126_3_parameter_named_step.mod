! expect: E0126 line 4
! a parameter named Step (STEP is reserved)
MODULE E0126_3
  PROC scale(num Step)
    TPWrite "scale";
  ENDPROC
ENDMODULE
