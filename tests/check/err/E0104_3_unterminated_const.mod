! expect: E0104 line 4
! an unterminated string in a module-level CONST
MODULE E0104_3
  CONST string msg := "oops;
  PROC main()
    TPWrite "main";
  ENDPROC
ENDMODULE
