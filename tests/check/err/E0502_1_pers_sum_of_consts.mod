! expect: E0502 line 9
! the manual's example: PERS num a__b := a + b (a negative literal is fine)
MODULE E0502_1
  CONST num a := 2;
  CONST num b := 3;
  CONST num ab := a + b;
  VAR num a_b := a + b;
  PERS num neg := -5;
  PERS num a__b := a + b;
ENDMODULE
