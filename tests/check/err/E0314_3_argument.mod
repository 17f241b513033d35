! expect: E0314 line 5
! an out-of-range num literal as an argument
MODULE E0314_3
  PROC main()
    WaitTime 1E40;
  ENDPROC
ENDMODULE
