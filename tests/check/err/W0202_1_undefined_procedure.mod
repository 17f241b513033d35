! expect: W0202 line 5
! a call to a procedure defined nowhere
MODULE W0202_1
  PROC main()
    MyProc;
  ENDPROC
ENDMODULE
