! expect: W0607 line 6
! RAISE of an errnum constant whose value is 100
MODULE W0607_3
  CONST errnum ERR_MINE := 100;
  PROC main()
    RAISE ERR_MINE;
  ENDPROC
ENDMODULE
