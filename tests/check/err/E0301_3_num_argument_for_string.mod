! expect: E0301 line 5
! a num passed where TPWrite wants a string
MODULE E0301_3
  PROC main()
    TPWrite 5;
  ENDPROC
ENDMODULE
