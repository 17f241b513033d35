! expect: E0505 line 5
! a PERS inside a FUNC
MODULE E0505_2
  FUNC bool ready()
    PERS bool flag := FALSE;
    RETURN TRUE;
  ENDFUNC
ENDMODULE
