! expect: E0401 line 8
! three arguments for a procedure with one parameter
MODULE E0401_2
  PROC show(num v)
    TPWrite "v: " \Num:=v;
  ENDPROC
  PROC main()
    show 1, 2, 3;
  ENDPROC
ENDMODULE
