! expect: E0203 line 5
! an undefined function inside an optional argument
MODULE E0203_3
  PROC main()
    TPWrite "square: " \Num:=Square(4);
  ENDPROC
ENDMODULE
