! expect: E0307 line 7
! a clock assigned
MODULE E0307_2
  VAR clock c1;
  VAR clock c2;
  PROC main()
    c1 := c2;
  ENDPROC
ENDMODULE
