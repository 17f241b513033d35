! expect: E0506 line 5
! LOCAL on a routine constant
MODULE E0506_2
  FUNC num f()
    LOCAL CONST num k := 1;
    RETURN 2;
  ENDFUNC
ENDMODULE
