! expect: E0204 line 6
! a record component of an undefined type
MODULE E0204_3
  RECORD lamp
    num watts;
    colour shade;
  ENDRECORD
ENDMODULE
