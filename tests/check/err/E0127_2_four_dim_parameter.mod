! expect: E0127 line 4
! a 4-dimensional array parameter
MODULE E0127_2
  PROC clear4(VAR num a{*,*,*,*})
    TPWrite "clear4";
  ENDPROC
ENDMODULE
