! expect: E0402 line 8
! one argument for a procedure with two parameters
MODULE E0402_2
  PROC add2(num a, num b)
    TPWrite "sum: " \Num:=a + b;
  ENDPROC
  PROC main()
    add2 1;
  ENDPROC
ENDMODULE
