! expect: W0605 line 9
! RETURN in an UNDO handler is ignored
MODULE W0605_2
  VAR num n;
  PROC main()
    n := 1;
  UNDO
    n := 0;
    RETURN;
  ENDPROC
ENDMODULE
