! expect: E0513 line 4
! alternatives between the second and third required parameters
MODULE E0513_2
  PROC p(num x, num a | string b)
    TPWrite "p";
  ENDPROC
ENDMODULE
