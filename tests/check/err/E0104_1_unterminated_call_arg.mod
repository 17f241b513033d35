! expect: E0104 line 5
! a string without its closing quote swallows the ';'
MODULE E0104_1
  PROC main()
    TPWrite "Hello;
  ENDPROC
ENDMODULE
