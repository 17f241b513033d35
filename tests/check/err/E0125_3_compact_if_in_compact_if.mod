! expect: E0125 line 6
! a compact IF is not a simple statement either
MODULE E0125_3
  VAR num n;
  PROC main()
    IF n > 0 IF n < 10 Incr n;
  ENDPROC
ENDMODULE
