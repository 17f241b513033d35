! expect: E0103 line 6
! a string literal of 81 characters (80 is fine)
MODULE E0103_1
  PROC main()
    TPWrite "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx";
    TPWrite "yyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyy";
  ENDPROC
ENDMODULE
