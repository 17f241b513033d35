! expect: E0211 line 6
! a variable name used as a data type
MODULE E0211_1
  VAR num cnt;
  PROC main()
    VAR cnt x;
    TPWrite "main";
  ENDPROC
ENDMODULE
