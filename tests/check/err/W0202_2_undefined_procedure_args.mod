! expect: W0202 line 6
! a call with arguments to a procedure defined nowhere
MODULE W0202_2
  VAR num n;
  PROC main()
    ProcessPart n, 2;
  ENDPROC
ENDMODULE
