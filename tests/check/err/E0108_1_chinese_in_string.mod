! expect: E0108 line 5
! UTF-8 file; a CJK character in a string is not Latin-1
MODULE E0108_1
  PROC main()
    TPWrite "中文";
  ENDPROC
ENDMODULE
