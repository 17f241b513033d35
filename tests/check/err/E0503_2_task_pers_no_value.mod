! expect: E0503 line 4
! a TASK PERS without an initial value
MODULE E0503_2
  TASK PERS num tp;
ENDMODULE
