! expect: E0209 line 5
! a parameter called like a procedure
MODULE E0209_3
  PROC run(num val)
    val;
  ENDPROC
ENDMODULE
