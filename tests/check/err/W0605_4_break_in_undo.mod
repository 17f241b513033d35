! expect: W0605 line 7
! Break in an UNDO handler of a FUNC is ignored
MODULE W0605_4
  FUNC num f()
    RETURN 1;
  UNDO
    Break;
  ENDFUNC
ENDMODULE
