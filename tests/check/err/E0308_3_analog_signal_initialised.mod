! expect: E0308 line 4
! an analog output signal declared with an initial value
MODULE E0308_3
  VAR signalao ao1 := 2.5;
ENDMODULE
