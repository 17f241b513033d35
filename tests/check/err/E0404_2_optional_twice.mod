! expect: E0404 line 8
! one optional argument given twice
MODULE E0404_2
  PROC show(\num x)
    IF Present(x) TPWrite "x: " \Num:=x;
  ENDPROC
  PROC main()
    show \x:=1 \x:=2;
  ENDPROC
ENDMODULE
