! expect: E0504 line 5
! a routine CONST without a value
MODULE E0504_2
  PROC main()
    CONST string s;
    TPWrite "main";
  ENDPROC
ENDMODULE
