! expect: E0210 line 9
! a PROC called in an expression
MODULE E0210_1
  VAR num n;
  PROC helper()
    TPWrite "helper";
  ENDPROC
  PROC main()
    n := helper();
  ENDPROC
ENDMODULE
