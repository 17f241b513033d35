! expect: E0502 line 5
! a PERS aggregate containing a data reference
MODULE E0502_2
  CONST num k := 100;
  PERS pos p := [0,0,k];
ENDMODULE
