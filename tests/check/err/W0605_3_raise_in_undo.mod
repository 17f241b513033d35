! expect: W0605 line 8
! RAISE with a valid number in an UNDO handler is ignored
MODULE W0605_3
  VAR num n;
  PROC main()
    n := 1;
  UNDO
    RAISE 10;
  ENDPROC
ENDMODULE
