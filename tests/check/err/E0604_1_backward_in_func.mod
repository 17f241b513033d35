! expect: E0604 line 6
! a BACKWARD handler in a FUNC
MODULE E0604_1
  FUNC num f()
    RETURN 1;
  BACKWARD
    TPWrite "back";
  ENDFUNC
ENDMODULE
