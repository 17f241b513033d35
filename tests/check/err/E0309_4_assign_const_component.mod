! expect: E0309 line 6
! an assignment to a component of a CONST
MODULE E0309_4
  CONST pos home := [0,0,500];
  PROC main()
    home.x := 5;
  ENDPROC
ENDMODULE
