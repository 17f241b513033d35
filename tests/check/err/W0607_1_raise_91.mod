! expect: W0607 line 5
! RAISE 91 is outside 1..90
MODULE W0607_1
  PROC main()
    RAISE 91;
  ENDPROC
ENDMODULE
