! expect: E0204 line 4
! a parameter of an undefined type
MODULE E0204_2
  PROC show(mytype a)
    TPWrite "show";
  ENDPROC
ENDMODULE
