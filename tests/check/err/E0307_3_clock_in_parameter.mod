! expect: E0307 line 9
! a clock passed to an IN parameter
MODULE E0307_3
  VAR clock c1;
  PROC show(clock c)
    TPWrite "show";
  ENDPROC
  PROC main()
    show c1;
  ENDPROC
ENDMODULE
