! expect: E0126 line 6
! a record component named to (TO is reserved)
MODULE E0126_4
  RECORD span
    num start;
    num to;
  ENDRECORD
ENDMODULE
