! expect: E0503 line 5
! a LOCAL PERS without an initial value
MODULE E0503_1
  PERS num global_p;
  LOCAL PERS num lp;
ENDMODULE
