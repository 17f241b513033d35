! expect: E0411 line 9
! named required arguments must still come in order
MODULE E0411_2
  PROC p(num a, num b)
    TPWrite "a: " \Num:=a;
  ENDPROC
  PROC main()
    p a:=1, b:=2;
    p b:=2, a:=1;
  ENDPROC
ENDMODULE
