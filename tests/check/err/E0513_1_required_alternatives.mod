! expect: E0513 line 4
! alternatives between required parameters
MODULE E0513_1
  PROC p(num a | num b)
    TPWrite "p";
  ENDPROC
ENDMODULE
