! expect: E0125 line 6
! a TEST as the statement of a compact IF
MODULE E0125_4
  VAR num n;
  PROC main()
    IF n > 0 TEST n
    CASE 1:
      Incr n;
    DEFAULT:
      Decr n;
    ENDTEST
  ENDPROC
ENDMODULE
