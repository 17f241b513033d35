! expect: E0602 line 5
! RETURN without a value in a FUNC (it has a RETURN, so no W0603)
MODULE E0602_2
  FUNC num f()
    RETURN;
  ENDFUNC
ENDMODULE
