! expect: E0301 line 5
! a FUNC num returning a string
MODULE E0301_4
  FUNC num f()
    RETURN "x";
  ENDFUNC
ENDMODULE
