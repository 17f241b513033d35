! expect: W0202 line 5
! a call with a switch to a procedure defined nowhere
MODULE W0202_3
  PROC main()
    GripperOpen \Fast;
  ENDPROC
ENDMODULE
