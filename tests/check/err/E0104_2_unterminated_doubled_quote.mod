! expect: E0104 line 6
! a string ending in a doubled quote is not terminated
MODULE E0104_2
  VAR string s;
  PROC main()
    s := "say ""hi"";
    TPWrite s;
  ENDPROC
ENDMODULE
