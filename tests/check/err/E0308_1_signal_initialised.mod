! expect: E0308 line 4
! a signal declared with an initial value
MODULE E0308_1
  VAR signaldi d := 1;
ENDMODULE
