! expect: E0303 line 6
! two aggregates added: neither operand gives the other a type (manual 1.3.3)
MODULE E0303_3
  VAR pos p;
  PROC main()
    p := [1,2,3] + [4,5,6];
  ENDPROC
ENDMODULE
