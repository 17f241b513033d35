! expect: W0605 line 8
! Stop in an UNDO handler is ignored
MODULE W0605_1
  VAR num n;
  PROC main()
    n := 1;
  UNDO
    Stop;
  ENDPROC
ENDMODULE
