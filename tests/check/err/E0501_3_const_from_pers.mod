! expect: E0501 line 5
! a CONST initialised from an expression over a PERS
MODULE E0501_3
  PERS num p := 1;
  CONST num c := p + 1;
ENDMODULE
