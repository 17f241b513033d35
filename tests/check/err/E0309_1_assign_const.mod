! expect: E0309 line 6
! an assignment to a CONST
MODULE E0309_1
  CONST num limit := 10;
  PROC main()
    limit := 20;
  ENDPROC
ENDMODULE
