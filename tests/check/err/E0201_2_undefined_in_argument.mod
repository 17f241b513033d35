! expect: E0201 line 5
! an undeclared name as an optional argument value
MODULE E0201_2
  PROC main()
    TPWrite "count: " \Num:=cnt;
  ENDPROC
ENDMODULE
