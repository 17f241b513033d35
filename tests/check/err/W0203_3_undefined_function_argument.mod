! expect: W0203 line 5
! an undefined function inside an optional argument
MODULE W0203_3
  PROC main()
    TPWrite "square: " \Num:=Square(4);
  ENDPROC
ENDMODULE
