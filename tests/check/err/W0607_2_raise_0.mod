! expect: W0607 line 6
! RAISE 0 is outside 1..90
MODULE W0607_2
  VAR num n;
  PROC main()
    IF n > 0 RAISE 0;
  ENDPROC
ENDMODULE
