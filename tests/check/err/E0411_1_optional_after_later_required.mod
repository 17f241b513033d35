! expect: E0411 line 9
! \b belongs between a and c
MODULE E0411_1
  PROC p(num a \num b, num c)
    TPWrite "a: " \Num:=a;
  ENDPROC
  PROC main()
    p 1 \b:=2, 3;
    p 1, 3 \b:=2;
  ENDPROC
ENDMODULE
