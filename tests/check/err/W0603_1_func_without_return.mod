! expect: W0603 line 5
! a FUNC with no RETURN at all (reported at FUNC)
MODULE W0603_1
  VAR num n;
  FUNC num f()
    n := 1;
  ENDFUNC
ENDMODULE
