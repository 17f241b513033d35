! expect: E0508 line 5
! a FUNC returning clock
MODULE E0508_1
  VAR clock c;
  FUNC clock get_clock()
    RETURN c;
  ENDFUNC
ENDMODULE
