! expect: E0501 line 5
! a CONST initialised from a VAR
MODULE E0501_1
  VAR num n := 1;
  CONST num c := n;
ENDMODULE
