! expect: E0209 line 6
! a variable called like a procedure
MODULE E0209_1
  VAR num cnt;
  PROC main()
    cnt;
  ENDPROC
ENDMODULE
