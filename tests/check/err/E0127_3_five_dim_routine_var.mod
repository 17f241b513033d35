! expect: E0127 line 5
! a 5-dimensional routine variable
MODULE E0127_3
  PROC main()
    VAR bool flags{2,2,2,2,2};
    TPWrite "main";
  ENDPROC
ENDMODULE
